#!/usr/bin/env bash
# The demo behind `./run demo`: the paper's Figs. 6 and 7 reproduced with the
# creepwork command-line program, the slip/adhesion maps of its Figs. 2-5,
# and the same Figs. 6-7 in SI.
#   usage: bash examples/paper_fig6.sh <creepwork binary> <output dir>
# The paper gives neither the semi-axes nor the material: `creepwork
# fit-fig6` fits the semi-axis a (b = a/2) to the printed Fx and Fy (steel
# G = 82 GPa, nu = 0.3, Kalker strip grid 10 x 10; see `creepwork fit-fig6
# --help`), prints the comparison with every printed number in the paper's
# units and SI, and writes the pictures of Figs. 6-9. --force: the demo
# replaces its own earlier output.
set -euo pipefail
cli=${1:?usage: paper_fig6.sh <creepwork binary> <output dir>}
out=${2:?usage: paper_fig6.sh <creepwork binary> <output dir>}

# The same contacts in SI (pictures in mm, N/mm^2 and kN), beside the other
# two runs (which write into one directory, one after the other).
"$cli" fit-fig6 --units si --out "$out-si" --force >/dev/null &
si=$!
# The paper's figures in the paper's units (ft, lbf, psi), forces on the rail
# as the paper prints them.
"$cli" fit-fig6 --units paper --out "$out" --force
"$cli" sweep --units paper --out "$out/maps" --force >/dev/null
wait "$si"
cat <<TEXT

Pictures (gnuplot scripts and data beside them; fields.csv, profile.csv and
result.json hold the numbers, with units in every column name):
  $out/patch.png       Fig. 6: the paper's eight panels over (x/a, y/b) -- slip/adhesion,
                       work (slip elements outlined), tractions, micro-slips, moment,
                       traction-bound utilisation; forces on the rail, as the paper
  $out/profile.png     Fig. 8: lateral work profile against the equal-area parabola
  $out/fig7/           Fig. 7 and Fig. 9 the same way
  $out/maps/fig2.png .. fig5.png   the slip/adhesion maps of Figs. 2-5
  $out-si/             Figs. 6-9 again in SI (mm, N/mm^2, kN)
One panel per file too: slip_adhesion.png work.png traction_x.png traction_y.png
slip_x.png slip_y.png moment.png utilisation.png work_paper.png.
TEXT
