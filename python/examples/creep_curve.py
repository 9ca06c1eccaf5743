"""A creep curve of 10 000 contacts in one call: solve_many broadcasts its
keywords as numpy does and solves every contact in C, on all cores."""
import numpy as np

import creepwork

xi_y = np.linspace(0.0, 5e-3, 10_000)  # lateral creepage [-]
out = creepwork.solve_many(a=7.0e-3, b=5.0e-3, N=100e3, xi_y=xi_y, model="calibrated")
print("solved %d of %d contacts" % (out.ok.sum(), out.status.size))
mu_N = out.params["mu"] * out.params["normal_force"]  # traction bound [N], per contact
for k in (500, 1000, 3000, 9999):
    print("xi_y = %.4f: -Fy/(mu N) = %.4f" % (xi_y[k], -out.Fy[k] / mu_N[k]))
