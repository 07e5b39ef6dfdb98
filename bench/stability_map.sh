#!/usr/bin/env bash
# fsi bench: where each fluid x solid pair is stable and accurate, explicit and implicit
# Stability maps (docs/stability.md): where each fluid x solid combination, with explicit
# (serial-staggered) and implicit coupling, stays stable and accurate on a scene
# sensitive to added mass, and what implicit coupling costs where explicit fails.
#
#   bench/stability_map.sh [OUT] [--axis density|stiffness|safety] [--values "LIST"]
#                          [--fluids "ulph wcsph"] [--solids "nosbpd"] [--schemes "serial_staggered plain implicit"]
#                          [--resume | --report] [--threads T] [--set k=v ...]
#
# The scene is C4 made small (cases/c4_plate_under_water.ini, docs/validation.md C4): the
# 1 m x 0.05 m clamped plate under a 0.5 m water column at T / dx = 4, 0.15 s. The plate
# under water has an analytic (2D plane-strain finite-element) static deflection, and the
# water column's added mass on its bending mode is about rho_w L / pi per unit area (318
# kg/m^2 against the aluminium plate's 135): lowering the plate's density raises the
# added-mass ratio without changing the static answer but for the plate's own weight.
# Axes:
#   density    the solid-to-fluid density ratio rho_s / rho_w (default "10 3 1 0.3 0.1 0.03 0.01");
#   stiffness  Young's modulus as a multiple of aluminium's 67.5 GPa (default "10 1 0.1 0.01");
#   safety     both sides' step factors as multiples of their defaults (fluid cfl_acoustic
#              or ISPH's courant_number, capped at 1; solid time_step_safety, capped at 4)
#              (default "0.5 1 2 4").
# Schemes: serial_staggered (explicit, with the solid's impedance answer inside the window,
# docs/coupling.md), plain (explicit without it: [solid] interface_impedance = false, the
# textbook serial-staggered scheme) and implicit (IQN-ILS, the defaults of [run]).
# Each run is OUT/AXIS/FLUID_SOLID_SCHEME/vVALUE (log beside it); writes OUT/AXIS.md and
# OUT/AXIS.png (bench/stability_map.py): stable and accurate, inaccurate (settled
# deflection more than 12 % from 2D elasticity, the T / dx = 4 discretisation error being
# +8 to +9 % on C4), or stopped (with the message), and for implicit runs the iterations
# per window.
set -euo pipefail
. "$(dirname "${BASH_SOURCE[0]}")/sweep.bash"
AXIS=density
VALUES=""
FLUIDS="ulph wcsph isph"
SOLIDS="nosbpd tlsph pseudo_spring"
SCHEMES="serial_staggered plain implicit"
ARGS=()
while [ $# -gt 0 ]; do
  case "$1" in
    --axis) AXIS="$2"; shift ;;
    --values) VALUES="$2"; shift ;;
    --fluids) FLUIDS="$2"; shift ;;
    --solids) SOLIDS="$2"; shift ;;
    --schemes) SCHEMES="$2"; shift ;;
    *) ARGS+=("$1") ;;
  esac
  shift
done
case "$AXIS" in
  density) : "${VALUES:=10 3 1 0.3 0.1 0.03 0.01}" ;;
  stiffness) : "${VALUES:=10 1 0.1 0.01}" ;;
  safety) : "${VALUES:=0.5 1 2 4}" ;;
  *) echo "stability_map: --axis is density, stiffness or safety" >&2; exit 2 ;;
esac
sweep_parse stability_map --values "$VALUES" ${ARGS[@]+"${ARGS[@]}"}

T=0.05; H=0.5; RHO_W=1000; E=67.5e9
dx=$("$PY" -c "print(repr($T / 4))")
SCENE=(--set "run.end_time=0.15" --set "fluid.block water.max=1,$H"
       --set "fluid.max_pressure=$("$PY" -c "print($RHO_W * 9.81 * $H)")"
       --set "fluid.spacing=$dx" --set "solid.spacing=$dx")

fluid_factor_key() {  # the fluid scheme's step factor and its default
  case "$1" in isph) echo "fluid.isph.courant_number 0.1" ;; *) echo "fluid.cfl_acoustic 0.25" ;; esac
}

DIRS=()
for f in $FLUIDS; do
  for s in $SOLIDS; do
    for scheme in $SCHEMES; do
      group="$OUT/$AXIS/${f}_${s}_$scheme"
      mkdir -p "$group"
      for v in $LIST; do
        case "$AXIS" in
          density) AX=(--set "solid.density=$("$PY" -c "print($v * $RHO_W)")") ;;
          stiffness) AX=(--set "solid.youngs_modulus=$("$PY" -c "print($v * $E)")") ;;
          safety)
            read -r key def <<<"$(fluid_factor_key "$f")"
            AX=(--set "$key=$("$PY" -c "print(min(1.0, $v * $def))")"
                --set "solid.time_step_safety=$("$PY" -c "print(min(4.0, $v * 0.8))")") ;;
        esac
        case "$scheme" in
          plain) SCH=(--set run.scheme=serial_staggered --set solid.interface_impedance=false) ;;
          *) SCH=(--set "run.scheme=$scheme") ;;
        esac
        log "$AXIS = $v: $f + $s, $scheme"
        sweep_run "$group/v$v" "$ROOT/cases/c4_plate_under_water.ini" "${SCENE[@]}" \
          --set "fluid.solver=$f" --set "solid.solver=$s" "${SCH[@]}" "${AX[@]}"
        DIRS+=("$group/v$v")
      done
    done
  done
done

"$PY" "$ROOT/bench/stability_map.py" --axis "$AXIS" --png "$OUT/$AXIS.png" --md "$OUT/$AXIS.md" \
  "${DIRS[@]}"
cat "$OUT/$AXIS.md"
log "report: $OUT/$AXIS.md, plot: $OUT/$AXIS.png"
