% creepwork quick start in MATLAB/Octave: creep forces and work map of one wheel-rail contact.
r = creepwork.solve('a', 7.0e-3, 'b', 5.0e-3, ...  % semi-axes along / across the rail [m]
                    'N', 100e3, ...                % wheel load [N]; steel, mu = 0.3 by default
                    'xi_x', 1.0e-3, 'xi_y', 5.0e-4, 'phi', 0.5);  % creepages [-], spin [1/m]
fprintf('Fx = %.1f N, Fy = %.1f N, Mz = %.3f N m (on the wheel)\n', r.Fx, r.Fy, r.Mz);
fprintf('W_macro = %.4f J/m, K = %.3f, adhesion %.0f %%\n', r.W_macro, r.K, ...
        100 * r.adhesion_fraction);
% Fields are nx-by-ny matrices: element (i, j) at (i+1, j+1), i along x.
fprintf('work of element (0, 10) at the trailing edge: %.3g J/m\n', r.fields.work_consistent(1, 11));
