#!/usr/bin/env bash
# The demo behind `./run demo`: the paper's Fig. 6 contact (and Fig. 7)
# reproduced with the creepwork command-line program, then the slip/adhesion
# maps of its Figs. 2-5.
#   usage: bash examples/paper_fig6.sh <creepwork binary> <output dir>
# The paper gives neither the semi-axes nor the material: `creepwork
# fit-fig6` fits the semi-axis a (b = a/2) to the printed Fx and Fy (steel
# G = 82 GPa, nu = 0.3, Kalker strip grid 10 x 10; see `creepwork fit-fig6
# --help`), prints the comparison with every printed number in the paper's
# units and SI, and writes the pictures of Figs. 6-9.
set -euo pipefail
cli=${1:?usage: paper_fig6.sh <creepwork binary> <output dir>}
out=${2:?usage: paper_fig6.sh <creepwork binary> <output dir>}

"$cli" fit-fig6 --units paper --out "$out"
echo
echo "Slip/adhesion maps of the paper's Figs. 2-5 (a/b = 2, the Fig. 6 contact):"
"$cli" sweep --units paper --out "$out/maps" >/dev/null
echo "  $out/maps/fig2.png .. fig5.png (creepages listed in $out/maps/cases.csv)"
echo
echo "Pictures of Fig. 6 in $out, of Fig. 7 in $out/fig7:"
echo "  patch.png      the eight panels of the paper's Figs. 6-7 (slip/adhesion, work,"
echo "                 tractions and micro-slips, moment, spin) over (x/a, y/b)"
echo "  profile.png    lateral work profile against the equal-area parabola (Figs. 8-9)"
echo "  slip_adhesion.png work.png traction_x.png traction_y.png slip_x.png slip_y.png"
echo "  moment.png spin.png work_paper.png: the panels one by one; fields.csv, profile.csv,"
echo "  result.json: the numbers behind them"
