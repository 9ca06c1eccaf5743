#!/usr/bin/env bash
# The table of doc/validation/transient.md "FASTSIM's transient form":
# CONTACT's catt_to_cart (a sphere, h = 2.963 (x^2 + y^2) [m] on 34 x 33
# cells of 0.25 mm from -4 mm; N = 0.4705 N, G = 1 MPa, nu = 0.28, mu =
# 0.4013), the Cattaneo shift to Fx = -0.657 mu N and 56 rolling steps of
# dx at that force, by the exact model and by FASTSIM's transient form,
# computed by `creepwork transient` (on PATH). Deterministic;
# scripts/doc-tables.sh pastes it.
set -euo pipefail
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
awk 'BEGIN { print "x_m,y_m,h_m"; for (j = 0; j < 33; j++) for (i = 0; i < 34; i++) {
  x = -4e-3 + i * 0.25e-3; y = -4e-3 + j * 0.25e-3
  printf "%.17g,%.17g,%.17g\n", x, y, 2.963 * (x * x + y * y) } }' >"$work/gap.csv"
awk 'BEGIN { print "dq_m,Fx"; for (k = 0; k < 57; k++)
  printf "%g,%.17g\n", (k ? 0.25e-3 : 0), -0.657 * 0.4013 * 0.4705 }' >"$work/steps.csv"
for model in exact fastsim; do
  creepwork transient --model "$model" --steps "$work/steps.csv" --gap "$work/gap.csv" \
    --prescribe forces --N 0.4705 --G 1e6 --nu 0.28 --mu 0.4013 2>/dev/null |
    awk '!/^#/ { print $1, $4, $10, $11 }' >"$work/$model.txt"
done
echo "| step | exact: xi_x | FASTSIM: xi_x | FASTSIM / exact - 1 | exact: adhesion, slip | FASTSIM: adhesion, slip |"
echo "|---:|---:|---:|---:|---:|---:|"
paste -d ' ' "$work/exact.txt" "$work/fastsim.txt" | awk '
  { rel = $6 / $2 - 1 }
  $1 > 1 && (m == "" || (rel < 0 ? -rel : rel) > m) { m = (rel < 0 ? -rel : rel); at = $1 }
  $1 == 1 || $1 == 2 || $1 == 5 || $1 == 10 || $1 == 15 || $1 == 16 || $1 == 20 || $1 == 22 ||
  $1 == 25 || $1 == 30 || $1 == 40 || $1 == 57 {
    printf "| %d%s | %.4e | %.4e | %+.1f %% | %d, %d | %d, %d |\n", $1, ($1 == 1 ? " (shift [m])" : ""),
      $2, $6, 100 * rel, $3, $4, $7, $8 }
  END { printf "\nLargest difference of a rolling step: %.1f %% (step %d).\n", 100 * m, at }'
