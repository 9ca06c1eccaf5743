"""creepwork quick start in Python: creep forces and work map of one wheel-rail contact."""
import creepwork

r = creepwork.solve(a=7.0e-3, b=5.0e-3,  # semi-axes along / across the rail [m] (creepwork.hertz)
                    N=100e3,             # wheel load [N]; steel, mu = 0.3 by default
                    xi_x=1.0e-3, xi_y=5.0e-4, phi=0.5)  # creepages [-] and spin [1/m]
print("Fx = %.1f N, Fy = %.1f N, Mz = %.3f N m (on the wheel)" % (r.Fx, r.Fy, r.Mz))
print("W_macro = %.4f J/m, K = %.3f, adhesion %.0f %%"
      % (r.W_macro, r.K, 100.0 * r.adhesion_fraction))
# Fields are numpy arrays of shape (ny, nx): element (i, j) at [j, i], i along x.
print("work of element (0, 10) at the trailing edge: %.3g J/m" % r.work_consistent[10, 0])
