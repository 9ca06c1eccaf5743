#!/usr/bin/env bash
# The campaign runner's threads: rank 0's scheduler beside its solver thread,
# and the batches' OpenMP threads, on 1 and 2 ranks with 2 threads each; the
# results must be bitwise equal. CI runs it under ThreadSanitizer too (label
# "threads"), as the program creepwork-campaign itself (the test carries its
# target's name, so that stage builds only it).
# usage: campaign_threads.sh <creepwork-campaign> <mpirun> <scratch dir>
set -euo pipefail
program=$1 mpirun=$2 dir=$3
rm -rf "$dir"
mkdir -p "$dir"
# 60 contacts over two grid shapes, partial and full slip, and two bad rows.
awk 'BEGIN {
  print "id,model,grid,nx,ny,a,b,N,mu,G,nu,xi_x,xi_y,phi"
  for (k = 0; k < 60; ++k) {
    grid = (k % 2) ? "uniform,10,8" : "strips,9,7"
    nu = (k == 17) ? "0.7" : "0.28"
    model = (k == 41) ? "exact" : "fastsim"
    printf "t%d,%s,%s,%.4g,%.4g,%.4g,0.3,82e9,%s,%.4g,%.4g,%.4g\n", k, model, grid,
      0.004 + 0.0003 * (k % 7), 0.003 + 0.0004 * (k % 5), 40000 + 3000 * (k % 9), nu,
      (k % 5 - 2) * 6e-4 * (k % 4 == 3 ? 20 : 1), (k % 3 - 1) * 5e-4, (k % 7 - 3) * 0.4
  }
}' >"$dir/in.csv"
for np in 1 2; do
  "$mpirun" --oversubscribe --bind-to none -np "$np" "$program" --in "$dir/in.csv" \
    --out "$dir/np$np" --threads 2 --chunk 3 --quiet
done
lines=$(wc -l <"$dir/np1/results.csv")
[ "$lines" -eq 61 ] || { echo "results.csv has $lines lines, expected 61"; exit 1; }
[ "$(grep -c ',ok,' "$dir/np1/results.csv")" -ge 58 ] || { echo "fewer than 58 rows solved"; exit 1; }
cmp "$dir/np1/results.csv" "$dir/np2/results.csv"
echo "1 and 2 ranks x 2 threads: results.csv bitwise equal ($((lines - 1)) rows)"
# The same rows with their wear (--wear: the wear solver's own threads and
# the merge of their profile accumulators).
awk -F, 'NR == 1 { print $0 ",s0,passes"; next } { printf "%s,%.4g,%d\n", $0, (NR % 7 - 3) * 1e-3, 100 + NR }' \
  "$dir/in.csv" >"$dir/wear.csv"
for np in 1 2; do
  "$mpirun" --oversubscribe --bind-to none -np "$np" "$program" --in "$dir/wear.csv" \
    --out "$dir/wear$np" --threads 2 --chunk 3 --quiet --wear
done
[ "$(grep -c ',ok,' "$dir/wear1/results.csv")" -ge 58 ] || { echo "fewer than 58 wear rows solved"; exit 1; }
cmp "$dir/wear1/results.csv" "$dir/wear2/results.csv"
cmp "$dir/wear1/wear_profile_rail.csv" "$dir/wear2/wear_profile_rail.csv"
echo "--wear, 1 and 2 ranks x 2 threads: results.csv and wear_profile_rail.csv bitwise equal"
