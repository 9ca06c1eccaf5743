#!/usr/bin/env python3
"""CONTACT's surface temperatures of its example ertz_temperature into
tests/data/temperature/ertz_fields.csv (what test_core_temperature reads).

CONTACT (Vollebregt & Kalker, github eve70a/CONTACT, commit d431cdb,
Apache-2.0), built as tests/data/README.md says, was run on its shipped
examples/ertz_temperature.inp
(unchanged, four cases, module 3, grid 216 x 45, dx = 0.2 mm):

    cd DIR && cp CONTACT/examples/ertz_temperature.inp . && contact 2 ertz_temperature

which writes ertz_temperature.000[1-4].mat. This script reads them:

    python3 ertz_fields.py DIR > tests/data/temperature/ertz_fields.csv

Kept (the values exactly as CONTACT printed them, 6 significant digits):
every contact element (eldiv 1 or 2; the same 1969 in all four cases), the
first five elements behind the trailing edge of every row in contact, and
the whole trail of the centre row (y = 0). Columns: ix, iy (CONTACT's
1-based indices, ix along x), then TEMP1 and TEMP2 [deg C] of cases 1-4.
"""
import sys


def read_mat(path):
    rows = [line.split() for line in open(path) if not line.startswith('%')]
    mx, my = int(rows[3][0]), int(rows[3][1])
    elements = rows[6:]
    if len(elements) != mx * my:
        raise SystemExit(f'{path}: {len(elements)} elements, expected {mx * my}')
    # columns: I IGS H MU PN PX PY UN UX UY SREL TEMP1 TEMP2
    return mx, my, [(int(r[1]), r[11], r[12]) for r in elements]


def main():
    folder = sys.argv[1]
    cases = [read_mat(f'{folder}/ertz_temperature.{c:04d}.mat') for c in range(1, 5)]
    mx, my, first = cases[0]
    state = [s for s, _, _ in first]
    for _, _, els in cases[1:]:
        if [s >= 1 for s, _, _ in els] != [s >= 1 for s in state]:
            raise SystemExit('the contact area differs between the cases')
    keep = set()
    centre_row = (my + 1) // 2  # 1-based: y = 0
    for iy in range(1, my + 1):
        row = [ix for ix in range(1, mx + 1) if state[ix - 1 + (iy - 1) * mx] >= 1]
        if not row:
            continue
        keep.update((ix, iy) for ix in row)
        trail = range(row[-1] + 1, mx + 1) if iy == centre_row else \
            range(row[-1] + 1, min(mx, row[-1] + 5) + 1)
        keep.update((ix, iy) for ix in trail)
    print('ix,iy,' + ','.join(f'T1_case{c},T2_case{c}' for c in range(1, 5)))
    for iy in range(1, my + 1):
        for ix in range(1, mx + 1):
            if (ix, iy) in keep:
                e = ix - 1 + (iy - 1) * mx
                values = ','.join(f'{els[e][1]},{els[e][2]}' for _, _, els in cases)
                print(f'{ix},{iy},{values}')


if __name__ == '__main__':
    main()
