#!/usr/bin/env bash
# The table of doc/validation/wear.md "Every model": one contact's macro work
# and USFD wear mass by the exact model and by FASTSIM on the same uniform
# grids, computed by the installed-style `creepwork wear` (on PATH) from the
# energy-consistent map. Deterministic; scripts/doc-tables.sh pastes it.
# Contact: a = 6 mm, b = 5 mm, N = 80 kN, mu = 0.3, G = 82 GPa, nu = 0.28,
# xi = (1e-3, 5e-4), phi = 0.4 1/m; box scale 1.2; one axle passage.
set -euo pipefail
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# totals N XI_X MODEL: "W_macro mass" of one wear run.
totals() {
  printf 's0,a,b,N,xi_x,xi_y,spin,passes,model,mu\n0,6e-3,5e-3,80e3,%s,5e-4,0.4,1,%s,0.3\n' \
    "$2" "$3" >"$work/s.csv"
  creepwork wear --in "$work/s.csv" --out "$work/o" --force --grid uniform --nx "$1" --ny "$1" \
    --box-scale 1.2 --nu 0.28 --no-plots >/dev/null 2>&1
  awk -F, 'NR == 1 { for (k = 1; k <= NF; ++k) c[$k] = k; next }
    { print $c["W_macro_J_per_m"], $c["mass_per_distance_kg_per_m"] }' "$work/o/states.csv"
}
echo "| n x n | exact: W_macro [J/m] | exact: USFD mass [kg/m] | FASTSIM: W_macro [J/m] | FASTSIM: USFD mass [kg/m] | exact / FASTSIM - 1 |"
echo "|---|---|---|---|---|---|"
for row in "12 1e-3" "24 1e-3" "48 1e-3" "48 8e-3"; do
  read -r n xi <<<"$row"
  read -r we me <<<"$(totals "$n" "$xi" exact)"
  read -r wf mf <<<"$(totals "$n" "$xi" fastsim)"
  label="$n x $n"
  [ "$xi" = 8e-3 ] && label="$n x $n, xi_x = 8e-3 (full slip)"
  awk -v l="$label" -v we="$we" -v me="$me" -v wf="$wf" -v mf="$mf" 'BEGIN {
    printf "| %s | %.5g | %.5g | %.5g | %.5g | %+.1f %% |\n", l, we, me, wf, mf, 100 * (me / mf - 1) }'
done
