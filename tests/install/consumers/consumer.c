/* A program outside the creepwork tree, built against an installed prefix
 * (find_package or pkg-config). Checks that the header and the loaded library
 * agree and that one of Kalker's 1982 check values comes out
 * (tests/data/kalker1982_checks.csv, row 4: TX = 0.5684). */
#include <math.h>
#include <stdio.h>

#include <creepwork/creepwork.h>

int main(void)
{
    if (cw_version_number() != CW_VERSION_NUMBER || cw_abi_version() != CW_ABI_VERSION) {
        fprintf(stderr, "header %d and library %d differ\n", CW_VERSION_NUMBER, cw_version_number());
        return 1;
    }
    double tx = 0, ty = 0;
    char message[256];
    if (cw_fastsim_normalised(1, -2, 2, 4, 5, 5, 3, &tx, &ty, message, sizeof message) != CW_OK) {
        fprintf(stderr, "cw_fastsim_normalised: %s\n", message);
        return 1;
    }
    printf("creepwork %s: TX = %.4f, TY = %.4f\n", cw_version_string(), tx, ty);
    return fabs(tx - 0.5684) <= 0.5e-4 ? 0 : 1;
}
