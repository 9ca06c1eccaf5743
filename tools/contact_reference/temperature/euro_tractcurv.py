#!/usr/bin/env python3
"""CONTACT's creep-force curves with temperature-dependent friction, from its
testbank example examples_temp/euro_tractcurv.ref_out, into
tests/data/temperature/contact_euro_tractcurv.csv (what test_capi_mu_temperature
reads).

CONTACT (Vollebregt & Kalker, github eve70a/CONTACT, commit d431cdb,
Apache-2.0) ships testbank/examples_temp/euro_tractcurv.inp and its output
euro_tractcurv.ref_out: module 3, steady rolling, exact theory on a 44 x 44
grid over 1.1 times the semi-axes (a = 6.304, b = 12.61 mm), FN = 106.7 kN,
G = 82000 N/mm^2, nu = 0.28, V = 10 m/s, both bodies steel at 0 deg C
(450 J/(kg K), 50 W/(m K), 7850 kg/m^3), 30 longitudinal creepages from
1e-5 to 0.25 per series. Series 1: Coulomb's 0.33; series 2-4: L=6 with
FREF 0.33, TREF 0 and DFHEAT, DTHEAT = (0.19, 1200), (-0.19, 1200),
(-0.19, 400).

    python3 euro_tractcurv.py CONTACT/testbank/examples_temp/euro_tractcurv.ref_out \\
        > tests/data/temperature/contact_euro_tractcurv.csv

One row per case, the values as CONTACT printed them: series, CKSI,
FX/FSTAT/FN (FSTAT = FREF = 0.33), MAX(T1,T2) [deg C], NCON, NADH, NSLIP.
"""
import sys


def cases(path):
    lines = open(path).read().splitlines()
    row = {}
    for k, line in enumerate(lines):
        if line.strip().startswith('CHI') and 'CKSI' in line:
            row['CKSI'] = lines[k + 1].split()[3]
        elif line.strip().startswith('FN/G') and 'MAX(T1,T2)' in line:
            v = lines[k + 1].split()
            row['FX_over_FSTAT_FN'] = v[1]
            row['T_MAX'] = v[5]
        elif line.strip().startswith('NPOT') and 'NSLIP' in line:
            v = lines[k + 1].split()
            row['NCON'], row['NADH'], row['NSLIP'] = v[1], v[2], v[3]
            yield row
            row = {}


def main():
    rows = list(cases(sys.argv[1]))
    if len(rows) != 120:
        raise SystemExit(f'{len(rows)} cases, expected 120')
    print('case,series,CKSI,FX_over_FSTAT_FN,T_MAX_C,NCON,NADH,NSLIP')
    for n, r in enumerate(rows):
        print(f"{n + 1},{n // 30 + 1},{r['CKSI']},{r['FX_over_FSTAT_FN']},{r['T_MAX']},"
              f"{r['NCON']},{r['NADH']},{r['NSLIP']}")


main()
