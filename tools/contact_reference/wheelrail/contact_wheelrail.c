/* contact_wheelrail.c - run CONTACT's library (module 1, wheel/rail) on input files and print its
 * geometric and contact results in full precision, one CSV row per (case, contact patch).
 *
 * Not part of creepwork's build: it links CONTACT (Vollebregt & Kalker, Apache-2.0), which
 * creepwork does not ship. Build against the library described in ../../../../shared/tools/contact:
 *   gcc -O2 contact_wheelrail.c -L$CONTACT/bin -lcontact -Wl,-rpath,$CONTACT/bin -lm -o contact_wheelrail
 * Usage:
 *   contact_wheelrail NAME.inp [NAME2.inp ...] > out.csv
 * Each NAME.inp is a complete CONTACT module-1 case (all control digits with Z = 3 and E = 3, so
 * the track, profiles and wheelset are read from that file alone); the profile files named in it
 * are looked up relative to the current directory. Units are CONTACT's: mm, N, mm/s, rad.
 * Columns: see the header line printed first. Every number is printed with %.17g.
 * With CW_CONTACT_XFLOW=2000 in the environment CONTACT also writes its debug dumps of the lateral
 * gap (dump_gap1d.m) and of the undeformed distance (dump_gap_ud<patch>.m) to the current directory.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void cntc_initializefirst(int *ifcver, int *ierror, int *ioutput, const char *c_wrkdir,
                          const char *c_outdir, const char *c_expnam, int *len_wrkdir,
                          int *len_outdir, int *len_expnam);
void cntc_initialize(int *ire, int *imodul, int *ifcver, int *ierror, const char *c_outdir, int *len_outdir);
void cntc_setglobalflags(int *lenflg, int *params, int *values);
void cntc_readinpfile(int *ire, int *inp_type, const char *c_fname, int *len_fname, int *ierror);
void cntc_setflags(int *ire, int *icp, int *lenflg, int *params, int *values);
void cntc_calculate(int *ire, int *icp, int *ierror);
void cntc_getnumcontactpatches(int *ire, int *npatch);
void cntc_getcontactlocation(int *ire, int *icp, int *lenarr, double *values);
void cntc_getreferencevelocity(int *ire, int *icp, double *veloc);
void cntc_getpenetration(int *ire, int *icp, double *pen);
void cntc_getcreepages(int *ire, int *icp, double *vx, double *vy, double *phi);
void cntc_getcontactforces(int *ire, int *icp, double *fn, double *tx, double *ty, double *mz);
void cntc_getglobalforces(int *ire, int *icp, int *lenarr, double *values);
void cntc_getpotcontact(int *ire, int *icp, int *lenarr, double *values);
void cntc_getmaximumpressure(int *ire, int *icp, double *pnmax);
void cntc_getwheelsetposition(int *ire, int *lenarr, double *values);
void cntc_getfielddata(int *ire, int *icp, int *ifld, int *lenarr, double *fld);
void cntc_finalize(int *ire);
void cntc_finalizelast(void);

/* magic numbers from CONTACT's src/caddon_flags.inc */
enum { CNTC_inp_modul1 = 1988, CNTC_if_idebug = 2000, CNTC_if_wrtinp = 2002, CNTC_ic_output = 1984,
       CNTC_ic_flow = 1985, CNTC_ic_xflow = 1981, CNTC_fld_h = 1 };

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: %s CASE.inp [CASE2.inp ...]\n", argv[0]);
        return 2;
    }
    int ifcver = 0, ierror = 0, ioutput = 0, lw = 1, lo = 1, le = 1;
    cntc_initializefirst(&ifcver, &ierror, &ioutput, ".", ".", "x", &lw, &lo, &le);
    int gf[2] = {CNTC_if_idebug, CNTC_if_wrtinp}, gv[2] = {0, 0}, ng = 2;
    cntc_setglobalflags(&ng, gf, gv);

    printf("case,z_ws,n_patches,patch,xcp_tr,ycp_tr,zcp_tr,deltcp_tr,xcp_r,ycp_r,zcp_r,scp_r,deltcp_r,"
           "xcp_w,ycp_w,zcp_w,scp_w,deltcp_w,xpn_tr,ypn_tr,xw_tr,yw_tr,zw_tr,rollw_tr,yaww_tr,yr_tr,zr_tr,rollr_tr,"
           "xcp_ws,ycp_ws,zcp_ws,deltcp_ws,"
           "pen,veloc,cksi,ceta,cphi,mx,my,xc1,yc1,dx,dy,h_min_field,fn,fx,fs,mn,pmax,"
           "fx_tr,fy_tr,fz_tr,fx_ws,fy_ws,fz_ws\n");
    for (int ia = 1; ia < argc; ++ia) {
        int ire = ia, imodul = 1, itype = CNTC_inp_modul1, len = (int)strlen(argv[ia]);
        cntc_initialize(&ire, &imodul, &ifcver, &ierror, ".", &lo);
        cntc_readinpfile(&ire, &itype, argv[ia], &len, &ierror);
        if (ierror != 0) {
            fprintf(stderr, "%s: readinpfile error %d\n", argv[ia], ierror);
            return 1;
        }
        /* CW_CONTACT_XFLOW=2000 (x_locate = 2) makes CONTACT dump its lateral gap samples to
           dump_gap1d.m and each patch's undeformed distance to dump_gap_ud<patch>.m */
        const char *xflow = getenv("CW_CONTACT_XFLOW");
        int icp0 = -1, fl[3] = {CNTC_ic_output, CNTC_ic_flow, CNTC_ic_xflow}, fv[3] = {0, 0, 0};
        int nf = xflow ? 3 : 2;
        if (xflow) fv[2] = atoi(xflow);
        cntc_setflags(&ire, &icp0, &nf, fl, fv);
        cntc_calculate(&ire, &icp0, &ierror);
        if (ierror != 0) {
            fprintf(stderr, "%s: calculate error %d\n", argv[ia], ierror);
            return 1;
        }
        double ws[6];
        int n6 = 6, npatch = 0;
        cntc_getwheelsetposition(&ire, &n6, ws);
        cntc_getnumcontactpatches(&ire, &npatch);
        double glob[9];
        int n9 = 9, icp1 = 1;
        cntc_getglobalforces(&ire, &icp0, &n9, glob);
        for (int icp = 1; icp <= npatch; ++icp) {
            double loc[33], veloc, pen, cksi, ceta, cphi, fn, fx, fs, mn, pot[6], pmax;
            int n33 = 33;
            cntc_getcontactlocation(&ire, &icp, &n33, loc);
            cntc_getreferencevelocity(&ire, &icp, &veloc);
            cntc_getpenetration(&ire, &icp, &pen);
            cntc_getcreepages(&ire, &icp, &cksi, &ceta, &cphi);
            cntc_getcontactforces(&ire, &icp, &fn, &fx, &fs, &mn);
            cntc_getpotcontact(&ire, &icp, &n6, pot);
            cntc_getmaximumpressure(&ire, &icp, &pmax);
            int npot = (int)(pot[0] * pot[1] + 0.5), ifld = CNTC_fld_h;
            double *h = malloc(sizeof(double) * (size_t)npot), hmin = 1e30;
            cntc_getfielddata(&ire, &icp, &ifld, &npot, h);
            for (int i = 0; i < npot; ++i) hmin = h[i] < hmin ? h[i] : hmin;
            free(h);
            printf("%s,%.17g,%d,%d", argv[ia], ws[2], npatch, icp);
            for (int k = 0; k < 14; ++k) printf(",%.17g", loc[k]);
            printf(",%.17g,%.17g", loc[14], loc[15]);
            for (int k = 20; k < 28; ++k) printf(",%.17g", loc[k]);
            for (int k = 29; k < 33; ++k) printf(",%.17g", loc[k]);
            printf(",%.17g,%.17g,%.17g,%.17g,%.17g", pen, veloc, cksi, ceta, cphi);
            printf(",%d,%d,%.17g,%.17g,%.17g,%.17g,%.17g", (int)pot[0], (int)pot[1], pot[2], pot[3],
                   pot[4], pot[5], hmin);
            printf(",%.17g,%.17g,%.17g,%.17g,%.17g", fn, fx, fs, mn, pmax);
            for (int k = 0; k < 3; ++k) printf(",%.17g", glob[k]);
            for (int k = 6; k < 9; ++k) printf(",%.17g", glob[k]);
            printf("\n");
        }
        (void)icp1;
        cntc_finalize(&ire);
    }
    cntc_finalizelast();
    return 0;
}
