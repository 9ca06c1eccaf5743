function r = solve(varargin)
%SOLVE  Creep forces, creep moment and work distribution of one wheel-rail contact.
%   R = creepwork.solve('a', 7e-3, 'b', 5e-3, 'N', 100e3, 'xi_x', 1e-3, ...
%                       'xi_y', 5e-4, 'phi', 0.5)
%   R = creepwork.solve(P, 'xi_x', 2e-3)   % P a struct of parameters
%
%   Parameters, SI units, each a field of the C struct cw_params with the
%   library's default (creepwork.params lists them): a, b semi-axes along x
%   (rolling) and y [m] and N (or normal_force) load [N], required; mu [-];
%   V rolling speed [m/s] (default 0, not given; Coulomb's law does not
%   use it); G [Pa] and nu [-] (steel by default); xi_x, xi_y creepages
%   [-]; phi (or spin) [1/m];
%   model 'fastsim' (default), 'calibrated' or 'exact'; pressure
%   'parabolic' or 'elliptic'; flexibility 'from_material' or 'given' with
%   L1, L2, L3 [m/Pa]; rolling_direction +1 or -1; tolerance,
%   max_iterations, warm_start (exact model); spin_offset,
%   flexibility_blending (FASTSIM); a friction law of the slip speed
%   (doc/theory/friction.md): friction_law 'linear', 'rational' or
%   'exponential' with mu the kinetic coefficient and its terms mu_e1,
%   s_h1, mu_e2, s_h2 [m/s], or 'polach', [mu0 A B] (B in s/m);
%   friction_speed 'local' (every element's slip speed, every field) or
%   'global' (FASTSIM) with k0, alpha_inf, beta;
%   memory_distance [m], memory_s0 [m/s] (FASTSIM, local); an interface
%   layer (the exact model on the uniform grid): layer_h [m], layer_G [Pa],
%   tau_c0 [Pa] (0: no yield), k_tau [Pa/m] (> 0 hardens, < 0 softens).
%   Options: 'grid', a struct of cw_grid fields (kind 'kalker_strips',
%   'uniform' or 'gap', nx, ny, box_scale; default Kalker's strips 20 x 20,
%   the exact model CONTACT's uniform 24 x 24 over 1.2 a x 1.2 b); 'fields',
%   false for the totals only (fastest). A gap ('gap', h) is an nx-by-ny
%   matrix, x along the first dimension.
%
%   R holds every field of cw_result (Fx, Fy [N] and Mz [N m] on the wheel,
%   W_macro [J/m], K, adhesion_fraction, n_contact, ...), and with fields:
%   R.fields.x, y, area, pz, px, py, sx, sy, mz, work_paper,
%   work_consistent, each an nx-by-ny matrix with element (i, j) at
%   (i+1, j+1), i along x; R.state (0 exterior, 1 adhesion, 2 slip); and
%   R.profile.y, w, parabola, the lateral work profile per strip.
%
%   Errors have the identifier creepwork:<status name>, e.g.
%   creepwork:CW_ERR_INVALID_INPUT, and the library's message naming the
%   input as the struct names it; a missing a, b or N is
%   creepwork:missingInput. Implausible values (a = 7.2 m, N in kN, a gap in
%   mm: the library's checks) warn with the identifier
%   creepwork:implausibleUnits.
%
%   See also creepwork.solve_many, creepwork.Solver, creepwork.jacobian.
  [p, opt] = creepwork.inputs(varargin{:});
  r = creepwork.call('solve', p, opt.grid, opt.fields, false);
end
