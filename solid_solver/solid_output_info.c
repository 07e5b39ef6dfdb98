#include "solid_output_info.h"

#include "solid_particles.h"
#include "units.h"

static const fsi_h5_field_info fields[] = {
    {"static/id", "1", "Stable particle id: the index at creation."},
    {"static/x0", "m", "Reference position of the particle (at t = 0)."},
    {"static/volume", FSI_UNIT_VOLUME, "Reference volume of the particle" FSI_PER_THICKNESS "."},
    {"static/density", "kg/m^3", "Reference density rho0 of the particle's material."},
    {"static/block", "1", "Index of the [solid.block] the particle came from, in case order."},
    {"static/flags", "1", "Boundary conditions of the particle, a sum of bits (flag_masks, "
                          "flag_meanings)."},
    {"displacement", "m", "Displacement from the reference position, x - x0."},
    {"velocity", "m/s", "Particle velocity."},
    {"acceleration", "m/s^2", "Particle acceleration."},
    {"interface_force", FSI_UNIT_FORCE, "Force of the fluid on the particle" FSI_PER_THICKNESS
                                        " over the last window, as received."},
    {"interface_pressure", "Pa", "Fluid pressure at the particle over the last window, as "
                                 "received."},
    {"mass", FSI_UNIT_MASS, "Particle mass rho0 V0" FSI_PER_THICKNESS
                            "; volume = mass / density."},
    /* every model writes it (NOSB-PD, pseudo-spring, TLSPH; fsi view draws it) */
    {"stress", "Pa", "Cauchy stress (row-major; the in-plane block in 2-D)."},
    {"density", "kg/m^3", "The density the solid shows the fluid: current for pseudo-spring "
                          "SPH (004 Eq. 14), the reference one for the total-Lagrangian "
                          "NOSB-PD and TLSPH."},
};

int solid_output_describe(fsi_h5_writer *out)
{
    static const int32_t bits[] = {SOLID_CLAMPED, SOLID_LOADED, SOLID_MIRRORED,
                                   SOLID_UNBREAKABLE};
    return fsi_h5_describe_fields(out, fields, (int)(sizeof fields / sizeof fields[0])) ||
                   fsi_h5_name_flags(out, "static/flags", FSI_H5_FLAG_MASKS, 4, bits,
                                     "clamped loaded mirrored unbreakable")
               ? -1
               : 0;
}
