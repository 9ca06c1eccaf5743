#!/usr/bin/env python3
"""Write one complete CONTACT module-1 input file per wheel/rail case (for contact_wheelrail.c).

Usage: make_cases.py CASES.csv OUTDIR
CASES.csv columns (CONTACT's units: mm, mm/s, rad, rad/s, N, 1/mm):
  name, side (left|right), norm (0: z_ws prescribed, 1: Fz prescribed), y_ws_mm, z_ws_mm, fz_N,
  roll_rad, yaw_rad, vs_mm_s, vpitch_rad_s, dx_mm, ds_mm
and optionally (defaults in brackets): vy_mm_s, vz_mm_s, vroll_rad_s, vyaw_rad_s [0],
  gaught_mm [14], gaugwd_mm [1435], raily0_mm, railz0_mm [0] (used when gaught <= 0),
  cant_rad [0], curv_1_mm [0], rail_dy_mm, rail_dz_mm, rail_roll_rad [0],
  a_sep_rad [pi/2], d_sep_mm [8], d_comb_mm [4].
Everything else is the Manchester benchmark A-2.2 set-up of CONTACT's examples/mbench_a22_*.inp
(UIC60 rail canted in the profile, S1002 wheel, flange-back distance 1360 mm, flange back at
-70 mm, nominal radius 460 mm, mu 0.3, G 82 GPa, nu 0.28, exact normal and tangential solvers,
EPS 1e-5). Profiles are read from OUTDIR: MBench_UIC60_v3.prr and MBench_S1002_v3.prw.
"""
import csv
import os
import sys

TEMPLATE = """\
  1 MODULE
 {C}203{NORM}00    C-P-B-T-N-F-S   CONFIG, PVTIME, BOUND,  TANG,   NORM,   FORCE,  STRESS
 0022033    V-L-D-C-M-Z-E   VARFRC, FRCLAW, DISCNS, INFLCF, MATER,  ZTRACK, EWHEEL
 0000001    H-G-I-A-O-W-R     HEAT, GAUSEI, IESTIM, MATFIL, OUTPUT, FLOW,   RETURN
    999     100    30    1     1e-5         MAXGS , MAXIN , MAXNR , MAXOUT, EPS
  0.300   0.300                                 FSTAT, FKIN
  0.280   0.280   82000.  82000.                POISS 1,2,  GG 1,2
  {DX}   {DS}   1.000   {ASEP}   {DSEP}   {DCOMB}      DX, DS, DQREL, A_SEP, D_SEP, D_COMB
  {GH}   {G2}   {G3}   {CANT}   {CURV}          GAUGHT, GAUGSQ|RAILY0, GAUGWD|RAILZ0, CANT, CURV
  'MBench_UIC60_v3.prr'   0     1.0   0.0       RFNAME, MIRRORY, SCALE, SMOOTH
  {RDY}   {RDZ}   {RROLL}   0.0   0.0   0.000     DY, DZ, ROLL, VY, VZ, VROLL
  1360.0  -70.0   460.0                         FBDIST, FBPOS, NOMRAD
  'MBench_S1002_v3.prw'   0     1.0   0.0       WFNAME, MIRRORY, SCALE, SMOOTH
  0.0  {Y}  {ZF}  {ROLL}  {YAW}  0.0      S, Y, Z/FZ, ROLL, YAW, PITCH
 {VS}  {VY}  {VZ}  {VROLL}  {VYAW}  {VPITCH} VS,VY,VZ, VROLL,VYAW,VPITCH

  0 MODULE
"""


def main():
    cases, outdir = sys.argv[1], sys.argv[2]
    os.makedirs(outdir, exist_ok=True)
    with open(cases, newline='') as f:
        for row in csv.DictReader(f):
            def get(key, default):
                value = row.get(key, '')
                return value if value not in (None, '') else default
            norm = int(row['norm'])
            gh = float(get('gaught_mm', '14.0'))
            text = TEMPLATE.format(
                C=1 if row['side'] == 'right' else 0, NORM=norm, DX=row['dx_mm'], DS=row['ds_mm'],
                ASEP=get('a_sep_rad', '90d'), DSEP=get('d_sep_mm', '8.0'), DCOMB=get('d_comb_mm', '4.0'),
                GH=gh, G2=get('raily0_mm', '0.0') if gh <= 0 else '0',
                G3=get('railz0_mm', '0.0') if gh <= 0 else get('gaugwd_mm', '1435.0'),
                CANT=get('cant_rad', '0.0'), CURV=get('curv_1_mm', '0.0'),
                RDY=get('rail_dy_mm', '0.0'), RDZ=get('rail_dz_mm', '0.0'), RROLL=get('rail_roll_rad', '0.0'),
                Y=row['y_ws_mm'], ZF=row['z_ws_mm'] if norm == 0 else row['fz_N'],
                ROLL=row['roll_rad'], YAW=row['yaw_rad'], VS=row['vs_mm_s'], VY=get('vy_mm_s', '0.0'),
                VZ=get('vz_mm_s', '0.0'), VROLL=get('vroll_rad_s', '0.0'), VYAW=get('vyaw_rad_s', '0.0'),
                VPITCH=row['vpitch_rad_s'])
            with open(os.path.join(outdir, row['name'] + '.inp'), 'w') as g:
                g.write(text)


if __name__ == '__main__':
    main()
