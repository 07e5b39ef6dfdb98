#include "fluid_output_info.h"

#include "fluid_particles.h"
#include "units.h"

static const fsi_h5_field_info fields[] = {
    {"static/id", "1", "Stable particle id: the index at creation."},
    {"static/x0", "m", "Particle position at t = 0."},
    {"static/flags", "1", "Kind of the particle (flag_values, flag_meanings)."},
    {"velocity", "m/s", "Particle velocity (prescribed for wall particles)."},
    {"acceleration", "m/s^2", "Particle acceleration of the last evaluation."},
    {"density", "kg/m^3", "Particle density; of a wall particle the equation of state's "
                          "density of its pressure (000 Eq. 53)."},
    {"pressure", "Pa", "Particle pressure; of a wall particle the fluid's pressure "
                       "extrapolated to it (000 Eq. 52)."},
    {"flags", "1", "Kind of the particle (flag_values, flag_meanings)."},
    {"mass", FSI_UNIT_MASS, "Particle mass" FSI_PER_THICKNESS "; volume = mass / density."},
};

int fluid_output_describe(fsi_h5_writer *out)
{
    /* One kind per particle: values, not bits. Moving boundary particles (the solid's)
     * are not in the fluid's frames, but the value is named for completeness. */
    static const int32_t kinds[] = {FLUID_PARTICLE_FLUID, FLUID_PARTICLE_WALL,
                                    FLUID_PARTICLE_MOVING_BOUNDARY};
    static const char meanings[] = "fluid wall moving_boundary";
    return fsi_h5_describe_fields(out, fields, (int)(sizeof fields / sizeof fields[0])) ||
                   fsi_h5_name_flags(out, "static/flags", FSI_H5_FLAG_VALUES, 3, kinds,
                                     meanings) ||
                   fsi_h5_name_flags(out, "flags", FSI_H5_FLAG_VALUES, 3, kinds, meanings)
               ? -1
               : 0;
}
