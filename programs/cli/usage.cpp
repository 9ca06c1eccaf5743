// The help texts: the CLI's documentation of commands, options, units,
// signs and output files.
#include "commands.hpp"

namespace cwcli {

const char* usage_main()
{
    return R"(usage: creepwork <command> [options]      (creepwork <command> --help for details)

Creep forces, creep moment and frictional-work distributions of a wheel
rolling on a rail, via libcreepwork: Kalker's simplified theory (FASTSIM, the
default), his exact half-space theory (--model exact) or the simplified
theory calibrated to the exact one (--model calibrated).

commands:
  solve      one contact: totals (text or JSON), and with --out every field
             as CSV plus pictures (the paper's Figs. 6-9)
  sweep      slip/adhesion maps for series of creepages (the paper's Figs. 2-5)
  fit-fig6   reproduce the paper's Figs. 6 and 7: fit the semi-axis to the
             printed forces, print the comparison, write the pictures
  wear       wear loop over a CSV of contact states: USFD or Archard wear
             accumulated on the rail or wheel profile, and the same with the
             paper's parabola assumption, as CSV and a picture
  campaign   many contacts from a CSV file, or a creep-force table, over MPI
             ranks and threads (built with MPI; creepwork campaign --help)
             (wear and campaign read the same columns: doc/input-schema.md)
  wheelrail  one wheel on one rail from the profiles: the wheelset height
             for a vertical force, every contact patch's position,
             creepages and forces by the exact theory or the fast model
             (CONTACT's module-1 conventions); with --out the profiles,
             every patch's fields and their pictures
  transient  transient rolling of a contact given by its gap: one step per
             line of a steps file (creepages or forces), tractions carried
             from step to step (doc/theory/transient.md)
  compare    one contact by FASTSIM (or --simplified: its elliptic bound,
             the calibrated model, all three) and by the exact theory on
             one grid: the totals, how far each work distribution is from
             the exact one, pictures side by side
  --version  program and library versions

exit status: 0 success, 1 environment failure (cannot write, gnuplot failed),
             2 bad input (one line on stderr names the option and the problem,
             with the nearest option or value when it looks like a typo)
stderr also carries warnings about inputs the library accepts but a
wheel-rail contact never has (a semi-axis of 7.2 m, G = 82000 Pa, a creepage
of 0.7), notes naming defaults taken, and where --out wrote; exit status 0.
Option names are exact (--N is the load, --nx the grid); values of
enumerations are not case sensitive (--units SI, --grid Uniform).

documentation: man creepwork; the manual under PREFIX/share/doc/creepwork,
where doc/index.md says what to read first and doc/cli.md covers this
program (doc/ paths in the help texts are relative to that directory).
)";
}

const char* usage_solve()
{
    return R"(usage: creepwork solve --a A --b B --N N [options]
       creepwork solve --gap FILE (--N N | --approach A) [options]

Solves one steady-rolling contact on an elliptical patch. The semi-axes and
the load are required (no default could fit a real contact). Everything else
has the library's default, named on stderr when taken for mu, G or nu:
steel G = 82 GPa, nu = 0.28, mu = 0.3, zero creepage; FASTSIM on Kalker's
strip grid 20 x 20, parabolic pressure.

model:
  --model fastsim|exact|calibrated
                    fastsim (default): Kalker's simplified theory. exact:
                    Kalker's exact half-space theory on CONTACT's
                    discretisation (doc/theory/exact.md): needs G and nu
                    (not --L1..--L3) and the uniform grid, and solves its own
                    normal problem (no --pressure). Without --grid it gets
                    CONTACT's layout: the uniform grid, 24 x 24 elements over
                    1.2 times the semi-axes (20 elements across the ellipse,
                    two guard cells on each side); --nx, --ny, --box-scale
                    override (at most 256 per direction); --grid
                    kalker_strips is an error. calibrated: the simplified theory calibrated to
                    the exact one (doc/theory/calibrated.md): needs G and nu,
                    its own pressure law (parabolic, blended towards Hertz's
                    as the slip grows; no --pressure).
  --tolerance T     exact model: relative residual at which the tangential
                    solve stops, in [1e-13, 1) (default 1e-8)
  --max-iterations N
                    exact model: bound on its Newton steps (default 50);
                    reaching it is an error (exit 2), never an unconverged
                    answer

contact (lengths, forces, stresses in the --units system):
  --a A             semi-axis along the rolling direction x (> 0), required
  --b B             lateral semi-axis (> 0; a/b within [1e-3, 1e3]), required
  --N N             normal force (>= 0), required
  --mu MU           friction coefficient (>= 0)
  --V V             rolling speed [m/s] in every --units system (>= 0;
                    default 0, not given); Coulomb's law does not use it
  --G G             combined shear modulus (> 0)
  --nu NU           combined Poisson's ratio (0 .. 0.5)
  --L1 L --L2 L --L3 L
                    flexibilities of the simplified theory, all three together
                    (replace G and nu; legacy codes give one L: pass it thrice)
  --xi-x XI         longitudinal creepage (-)
  --xi-y XI         lateral creepage (-)
  --spin PHI        spin creepage (1/length); --phi is the same option
  --rolling-direction +1|-1
                    +1 (default): rolling towards +x, leading edge at x = +a
  --pressure parabolic|elliptic
                    normal pressure and traction bound (default parabolic,
                    the simplified theory; elliptic = Hertz)
  --spin-offset S   spin term of the lateral rigid slip taken S element
                    lengths ahead of the slip point (0 .. 1; default 0,
                    Kalker's FASTSIM; CONTACT's FASTSIM uses 1/6; the exact
                    model's default is 1/6, CONTACT's)
  --flexibility-blending
                    CONTACT's blending of L1, L2, L3 towards one flexibility
                    as the creepage grows (CONTACT's FASTSIM default). With
                    --grid uniform --spin-offset 0.1666666666666667 this
                    reproduces CONTACT's FASTSIM output.
  --exact-load      FASTSIM and the calibrated model: the pressure scaled so
                    that its sum over the grid, sum(pz dA), is N, and so
                    |F| <= mu N to rounding (default: the pressure law's
                    analytic scale, whose sum differs from N by up to a few
                    tenths of a per cent, the original algorithm; the exact
                    model carries N exactly either way)
friction falling with the slip speed s = |micro-slip| V (FASTSIM and the
exact model, also with --gap; doc/theory/friction.md):
  --friction-law coulomb|linear|rational|exponential|polach
                    CONTACT's laws (its L = 2, 3, 4): mu is then the kinetic
                    coefficient mu_kin, each term falls from --mu-e1 (--mu-e2)
                    at s = 0 to half of it at --s-h1 (--s-h2); the static
                    coefficient is mu + mu_e1 + mu_e2. Needs --V > 0
  --mu-e1 M --s-h1 S --mu-e2 M --s-h2 S
                    the falling terms [-] and their half speeds [m/s in every
                    --units system] (CONTACT's FEXP1, SABSH1/1000, ...)
  --polach MU0,A,B  Polach's mu0 [(1 - A) exp(-B s) + A], B in s/m, as the
                    exponential law (instead of --friction-law and --mu);
                    --friction-law polach --mu MU0 --polach-A A --polach-B B
                    is the same
  --friction-speed local|global
                    local (default): the law at each element's slip speed
                    (every field, --out too); global: FASTSIM with mu at
                    the contact's slip speed V |(xi_x, xi_y)| as CONTACT's
                    FASTSIM, every field
  --k0 K --alpha-inf A --beta B
                    global: Spiryagin's slope reduction of the flexibilities
                    (defaults 1, 1, 0: none)
  --memory-distance D --memory-s0 S
                    local: CONTACT's friction memory over the slip distance D
                    (length) with background slip speed S [m/s]
interface (third-body) layer, --model exact:
  --layer-h H --layer-G G3
                    an elastic layer of thickness H (length) and shear modulus
                    G3 (stress) in series with the bodies (only H/G3 matters)
  --tau-c0 T        the layer's yield stress in shear (stress; default 0: no
                    yield); with --layer-h 0 the surface yields. Coulomb's
                    law, the ellipse's grid (not --gap)
  --k-tau K         hardening (> 0) or softening (< 0) of the yield stress
                    with the plastic displacement accumulated along the
                    contact [Pa/m in every --units system; CONTACT's N/mm^3
                    times 1e9]; needs --tau-c0; default 0: perfectly plastic
contact of any shape (instead of --a, --b and the grid options):
  --gap FILE        the undeformed distance on a regular grid: a CSV file with
                    the header x_m,y_m,h_m and one line per cell centre (any
                    order; in metres whatever --units says; positive h =
                    separation). Its cells are the potential contact area; it
                    is solved by the exact model (default) or by FASTSIM
                    (--model fastsim: each patch with the flexibilities of its
                    own ellipse), separate patches together (reported one by
                    one); Mz about the file's origin
  --approach A      with --gap, instead of --N: the approach from the file's
                    h = 0 (length)
  --normal-method exact|semi_hertz
                    with --gap: the half-space normal problem (default) or,
                    fast, a Hertzian semi-ellipse per row (Sichani et al.)
grid:
  --grid kalker_strips|uniform
                    Kalker's strip grid (default; or strips) or CONTACT's
                    uniform grid
  --nx N --ny N     elements per strip and number of strips (1 .. 1000)
  --box-scale S     uniform grid box [-S a, S a] x [-S b, S b], S in [1, 100]
surface temperature and damage (SI whatever --units; body 1 is the rail,
body 2 the wheel):
  --temperature     also the steady flash temperature of both surfaces from
                    the frictional power (doc/theory/temperature.md); needs
                    the rolling speed, --V or --speed
  --speed V         the rolling speed [m/s] of --temperature (default --V;
                    both given must be the same)
  --T0-1 T --T0-2 T bulk temperature of the rail and of the wheel [degC]
                    (default 20)
  --heat-capacity-1 C --heat-capacity-2 C
                    specific heat capacity [J/(kg K)] (default 450, steel)
  --conductivity-1 L --conductivity-2 L
                    thermal conductivity [W/(m K)] (default 50, steel)
  --density-1 R --density-2 R
                    density [kg/m^3] (default 7850, steel)
  --temperature-discretisation consistent|contact
                    consistent (default): the exact integral of the heat of
                    each element, from the energy-consistent work map, one
                    surface temperature in contact; contact: CONTACT's
                    discretisation (its element's own term runs hot, of
                    order sqrt(dx)), for comparison with CONTACT
  --mu-T "T1:mu1,T2:mu2,..."
                    friction that depends on the temperature: mu piecewise
                    linear in the rail's surface temperature [degC],
                    constant beyond the ends (CONTACT's L=6 is two points);
                    solved in a fixed-point loop of solve and temperature
                    (JSON: temperature_iterations); --model exact or
                    fastsim (also on --gap; not with --friction-speed
                    global); under a --friction-law the table gives the
                    coefficient at rest
  --k-yield K       also the damage indices with the surface shear yield
                    stress K [Pa] (doc/theory/damage.md): the RCF index per
                    element, FI_surf, T_gamma and the WLRM damage per pass
units:
  --units si|paper  si (default): m, N, Pa, 1/m, N m, J/m.
                    paper: the units the paper prints -- ft, lbf, 1/ft,
                    lbf ft, work per rolled distance in lbf ft/ft; G and
                    tractions in psi; L1..L3 in ft/psi.
output:
  --format text|json
                    totals on stdout (default text)
  --out DIR         also write DIR/fields.csv, profile.csv, result.json and
                    the pictures (all or nothing: staged, then renamed);
                    stderr says how many files went where
  --force           with --out: replace DIR if an earlier creepwork run
                    wrote it (a directory creepwork did not write is never
                    replaced)
  --no-plots        with --out: data files only
  --jacobian        also the 4 x 4 Jacobian of Fx, Fy, Mz, W_macro by xi_x,
                    xi_y, phi, N (SI, whatever --units): "jacobian" in the
                    JSON, a table in the text (doc/theory/jacobians.md); with
                    --gap, d/dN along the solution, also with --approach
  --plot-sign wheel|rail
                    the body the pictures' tractions, forces and moment act
                    on; default wheel, the sign of solve's text, JSON and CSV
  --plot-axes normalised|physical
                    pictures over x/a, y/b (default: every patch a circle,
                    as the paper draws it) or over x, y in mm (in with
                    --units paper): a 2:1 patch drawn as a 2:1 ellipse

signs: Fx, Fy, Mz, px, py, mz are the library's: they act on the WHEEL,
opposite to the creepages (Kalker, CONTACT). The paper prints the force on
the rail. Work is positive when dissipated, per unit rolling distance.
Pictures: SI in mm, N/mm^2 (tractions), kN (forces), N m, J/m; --units
paper in in, psi, lbf, lbf ft, lbf ft/ft.

JSON keys (stable; values in the --units system):
  Fx Fy Mz W_macro W_micro_paper K W_consistent balance_factor work_flags
  adhesion_fraction n_contact n_adhesion n_slip a b L1 L2 L3 C11 C22 C23 C33
  profile_max_diff profile_rms_diff model p_max approach iterations residual
  units sign_convention input{} unit_of{}
  W_macro = -(Fx xi_x + Fy xi_y + Mz spin) (paper eq. 34); W_micro_paper is
  the paper's summed local work and K = W_macro / W_micro_paper (eq. 39);
  W_consistent sums the energy-consistent work map (= W_macro). model is
  fastsim, exact or calibrated; p_max the largest element pressure, approach
  the normal approach (exact: of its discrete normal problem; FASTSIM:
  Hertz's); iterations and residual those of the exact model's solve (0 for
  the simplified models).
  With --model exact, work_paper is the exact frictional power density
  (CONTACT's FRIC_POWER) and K = W_macro over its sum.
  With --temperature (SI): T_max_1 T_max_2 (degC: each body's hottest
  contact element) T_max_x T_max_y (m: where the hotter one is)
  contact_temperature (degC) power (W) temperature_iterations
  temperature_discretisation. With --k-yield: rcf_index_max rcf_index_x
  rcf_index_y (m) mu_eff FI_surf T_gamma (N = W_macro) wlrm_damage (per
  pass).

files with --out:
  fields.csv   one row per element, i fastest (nx*ny rows), the unit in
               every column name (SI shown):
               i,j,x_m,y_m,area_m2,state,pz_Pa,px_wheel_Pa,py_wheel_Pa,sx,sy,
               mz_wheel_N_m,work_paper_J_per_m,work_consistent_J_per_m
               state 0 exterior, 1 adhesion, 2 slip; sx, sy = W/V (-);
               mz, work_* per element (moment, work per rolled distance)
  profile.csv  j,y_m,w_J_per_m_per_m,parabola_J_per_m_per_m: lateral work
               profile (per unit width) and the equal-area parabola (paper
               Figs. 8-9)
  result.json  the JSON above
  patch.png    eight panels after the paper's Figs. 6-7: slip/adhesion,
               work per area (slip elements outlined), tractions and
               micro-slips, moment per area, and the traction-bound
               utilisation |p|/(mu pz) in place of the paper's spin panel
               (which is one constant colour in slip)
  slip_adhesion.png work.png traction_x.png traction_y.png slip_x.png
  slip_y.png moment.png utilisation.png work_paper.png profile.png
  gnuplot/     the scripts and data behind the pictures
               (cd DIR && gnuplot gnuplot/patch.gp re-draws them)
  temperature_rail.png temperature_wheel.png
               with --temperature: each body's surface temperature over the
               grid in mm, the contact outlined, its maximum ringed
  rcf_index.png
               with --k-yield: the RCF index, its maximum ringed
  with --gap, the pictures over x, y of the whole grid (mm; in with --units
  paper; --plot-axes normalised is an error: a gap has no semi-axes):
  patch.png    six panels under the inputs and totals (Fn, Fx, Fy, Mz,
               each patch's forces): the gap h with the contact outlined,
               the pressure, slip/adhesion with each patch labelled at its
               centroid (numbered as in the text and JSON), work per area
               (slip elements outlined) and the tractions px, py
  gap.png pressure.png slip_adhesion.png work.png traction_x.png
  traction_y.png
  gnuplot/     gap.gp and its data; patches.dat: one row per patch

example (the paper's Fig. 6 contact in its units):
  creepwork solve --units paper --a 0.0217594 --b 0.0108797 --N 10000 --mu 0.6 \
      --G 11893094 --nu 0.3 --xi-x 0.0019 --xi-y 0.0011 --spin 0.144 \
      --nx 10 --ny 10 --out fig6
)";
}

const char* usage_sweep()
{
    return R"(usage: creepwork sweep --out DIR [options]

Slip/adhesion maps for the series of creepages of the paper's Figs. 2-5
(a/b = 2): one PNG per figure, each a grid of panels.
  fig2.png  zero spin, xi_x = xi_y increasing
  fig3.png  zero lateral creepage, xi_x increasing; small spin (top row),
            large spin (bottom row)
  fig4.png  zero longitudinal creepage, xi_y from negative to positive;
            small spin (top row), large spin (bottom row)
  fig5.png  pure spin, increasing
The paper prints no creepage values for these figures. The series are set
relative to the contact's own saturation creepages, so they keep their
meaning for any contact: xi_c = 2 mu p0 L1 / a is the longitudinal creepage
at which the centre strip of the simplified theory slips completely
(p0 = 2N/(pi a b), parabolic), eta_c = 2 mu p0 L2 / a the lateral one, and
phi_c = 2 mu p0 L3 / a^2 the spin at which the centre strip slips.

contact (defaults: the paper's Fig. 6 contact as fitted by fit-fig6 --
a = 6.6323 mm, b = a/2, N = 10000 lbf, mu = 0.6, G = 82 GPa, nu = 0.3,
Kalker strip grid 40 x 40): --a --b --N --mu --G --nu --L1 --L2 --L3
--pressure --rolling-direction --exact-load --grid --nx --ny --box-scale
--units --model --tolerance --max-iterations (as for solve; --model exact without
--grid: the uniform grid 48 x 48 over 1.2 times the semi-axes).
output: --out DIR (required), --force, --format text|json (the table of
cases on stdout), --no-plots. DIR gets cases.csv (one row per panel: figure,
panel, xi_x, xi_y, spin, Fx, Fy, Mz on the wheel, adhesion_fraction, n_slip,
n_contact) and fig2.png .. fig5.png with their gnuplot/ scripts.
progress: on a terminal, a line on stderr after 2 s and then every 10 s
(maps solved, rate, time to go); --progress S a line every S seconds,
terminal or not; --quiet none.
)";
}

const char* usage_fit_fig6()
{
    return R"(usage: creepwork fit-fig6 [--out DIR] [options]

Reproduces the paper's Figs. 6 and 7, whose semi-axes and material the
paper does not give.
Fig. 6: xi_x = 0.0019, xi_y = 0.0011, spin = 0.144 1/ft, a/b = 2, mu = 0.6,
  N = 10000 lbf; printed Fx = 2780.880 lbf, Fy = 3789.320 lbf,
  Mz = 2.385 lbf ft, Wd = 9.795, K = 1.602 (Table 1).
  The semi-axis a (b = a/2) is fitted by least squares on the two printed
  forces: a scan of a over [1, 40] mm finds every local minimum, golden-
  section search refines each. The forces reach the printed values on two
  branches; the one whose creep moment agrees with the printed Mz is taken
  (the other is nearly full slip with a moment 20 times larger). All minima
  are printed. At the fitted a our creep moment, the plain integral of
  (x py - y px), is 2.42 lbf ft: the printed Mz is the moment itself (no
  extra factor a), and the printed Wd = Fx xi_x + Fy xi_y + Mz spin uses it.
Fig. 7: xi_x = 0, xi_y = 0.0022, spin = 0.576 1/ft, a/b = 1.8, mu = 0.6,
  N = 6345.8 lbf; printed Fy = 3255.332 lbf, Mz = 9.971 lbf ft,
  Wd = 12.905, K = 1.424. Its a is fitted the same way to the printed Fy
  (the contact differs from Fig. 6's -- other a/b, other load -- so Hertz
  scaling of Fig. 6's a is only shown for comparison).
Defaults: steel G = 82 GPa, nu = 0.3; parabolic pressure (paper eq. 16);
Kalker strip grid 10 x 10. The paper's grid is not given, and K depends on
it (K -> 1 as it is refined); about ten elements per strip reproduces the
printed K of both figures: 1.627 (1.602) and 1.414 (1.424). With nu = 0.3
the printed Mz, Wd and K of both figures agree within 1.7 %; nu = 0.25
fits the Fx/Fy ratio better (RMS force misfit 4.5 lbf instead of 22) but
Mz, Wd and K only within 3.1 %.
Table 1: every row's K, rows 1-4, 6, 7 on Fig. 6's fitted contact (the
paper does not say which contact they used), row 5 on Fig. 7's.

options: --G --nu --nx --ny --units si|paper (units of --G, the JSON, the
files and the pictures; the text shows both), --format text|json|markdown
(markdown: the comparison and Table 1 as the tables of the documentation's
doc/validation/paper.md), --out DIR
(pictures of Fig. 6 in DIR, of Fig. 7 in DIR/fig7, plus fields.csv,
profile.csv, result.json in each), --force, --no-plots, --plot-sign
wheel|rail (default rail: the comparison above is on the rail, as the paper
prints it; the CSV and JSON files give the wheel's), --plot-axes
normalised|physical.
)";
}

const char* usage_wear()
{
    return R"(usage: creepwork wear --in STATES.csv --out DIR [options]

A wear loop: each contact state of STATES.csv is solved, its wear computed
element by element from the frictional work (doc/theory/wear.md), and its
lateral wear profile added, the state's number of passes times, to a profile
grid at the state's position s0. The same is done with the paper's assumption that
the work (and so the wear) is spread laterally as a parabola (Figs. 8-9):
the same worn volume per pass, (3V/4b)(1 - y^2/b^2) over [-b, b].
A pass is one passage of the body's material through the contact: an axle
passage for the rail, a wheel revolution for the wheel.

STATES.csv: a header line naming the columns (any order; '#' lines and
blank lines are skipped), then one state per line, SI units. The columns
are those of `creepwork campaign` (doc/input-schema.md): a file one command
reads, the other reads too.
  s0             profile coordinate of the patch centre [m]       required
  a, b           semi-axes along x (rolling) and y [m]            required
  N              normal force [N]                                 required
  xi_x, xi_y     creepages [-]                                    default 0
  phi (or spin)  spin creepage [1/m]                              default 0
  contact_angle  angle of the contact plane to the s axis [rad]   default 0
                 (0: s runs along the surface; else s is the lateral
                 coordinate and depths are also given vertically/radially)
  passes         passes this state stands for: axle passages (rail),
                 wheel revolutions (wheel)
  distance       instead of passes, --body wheel only: rolled distance [m],
                 passes = distance / (2 pi R) (needs --wheel-radius)
  speed          rolling speed [m/s] (Archard)                    default --speed
  body           rail|wheel: must be --body's (one body per run)
  mu, G, nu      friction, shear modulus [Pa], Poisson's ratio    default --mu ...
  model          fastsim (default), exact or calibrated
  grid, nx, ny, box_scale
                 the grid (default --grid, --nx, --ny; the exact model:
                 uniform 24 x 24 over 1.2 a, 1.2 b): one for every state
  pressure, rolling_direction, spin_offset, flexibility_blending, L1, L2,
  L3, tolerance, max_iterations: as the options of `creepwork solve`
  id             a campaign's row name: ignored (with a note)
Every state needs passes (or, for a wheel, distance). An empty cell takes
the default. Values the library accepts but a wheel-rail contact never has
(a = 7.2 m, N = 80 for 80 kN, a contact angle of 1.4 rad) are
warned about on stderr, naming the line and column, in the words of
`creepwork solve` and `creepwork campaign`.

wear law:
  --law usfd|archard
                    usfd (default): Braghin et al., Wear 261 (2006): wear
                    rate 5.3 T/A, 55.0, 61.9 T/A - 4778.7 ug/(m mm^2) below
                    10.4, to 77.2, above 77.2 N/mm^2 (R8T/900A);
                    archard: k N s / H with k from the KTH map (Jendel,
                    Wear 253 (2002)): needs --speed
  --source consistent|paper|slip
                    the frictional work fed to the law: the energy-
                    consistent map (default), the paper's eq. 36 map, or the
                    model's traction x micro-slip
  --speed V         rolling speed [m/s] (Archard's sliding velocity)
  --density RHO     [kg/m^3], default 7800
  --hardness H      Archard: [Pa], default 2.5e9
  --body rail|wheel default rail; mass per metre of rail
  --wheel-radius R  [m], --body wheel: passes from distance, mass per wheel
  --orientation +1|-1
                    +1 (default): s grows with the contact's y
contact: --mu --G --nu (defaults 0.3, 82e9 Pa, 0.28) --pressure
  parabolic|elliptic --exact-load (as for solve; the defaults of the
  columns); grid: --grid kalker_strips|uniform --nx --ny --box-scale
  (default Kalker strips 20 x 20)
profile grid: --profile-from S --profile-to S --profile-step DS [m]
  (default: every patch s0 -+ b plus 20 %, spacing a quarter of the
  narrowest strip)
output: --out DIR (required; all or nothing), --force, --no-plots,
  --format text|json (the summary on stdout)
progress: on a terminal, a line on stderr after 2 s and then every 10 s
  (states solved, rate, time to go); --progress S a line every S seconds,
  terminal or not; --quiet none

files in DIR:
  wear_profile.csv  k,s_m,depth_normal_m,depth_height_m,
                    parabola_depth_normal_m,parabola_depth_height_m:
                    accumulated depth at each node, normal to the surface
                    and along the profile's height axis (vertical on a rail,
                    radial on a wheel: normal / cos(contact angle))
  states.csv        one row per state: line,s0_m,a_m,b_m,N_N,xi_x,xi_y,
                    spin_per_m,contact_angle_rad,passes,Fx_wheel_N,
                    Fy_wheel_N,W_macro_J_per_m,work_J_per_m,
                    mass_per_distance_kg_per_m,mass_per_pass_kg,
                    max_depth_per_pass_m,area_regime1_m2..area_regime4_m2
  summary.json      body law source states nodes passes volume_m2
                    volume_lost_m2 mass_kg peak_depth_height_m peak_s_m
                    parabola_peak_depth_height_m parabola_peak_s_m mass_per
  wear.png          both depth profiles over s (gnuplot/ holds the script)

example (two states of one rail section, 500 axle passages each):
  printf 's0,a,b,N,xi_x,spin,passes\n0.002,6e-3,4e-3,60e3,1e-3,0.5,500\n-0.003,6e-3,4e-3,60e3,-1e-3,2.0,500\n' > s.csv
  creepwork wear --in s.csv --out wear-out
)";
}

const char* usage_compare()
{
    return R"(usage: creepwork compare [options]

One contact solved twice on the same uniform grid: by FASTSIM (Kalker's
simplified theory, parabolic pressure, the paper's) and by Kalker's exact
half-space theory (doc/theory/exact.md). Prints both models' totals and how
far FASTSIM's frictional-work distribution is from the exact one -- what the
paper could not check. Distances compare shapes: each map is scaled to unit
total first.
  --simplified fastsim|fastsim-elliptic|calibrated|all
                     the simplified side (default fastsim): FASTSIM with the
                     paper's parabolic traction bound, with the elliptic
                     one, the calibrated model (doc/theory/calibrated.md),
                     or all three at once. "fastsim" in the metric names
                     below stands for the simplified model compared.
  map_l1_consistent  sum |f/F - e/E| over the elements of the two energy-
                     consistent work maps (0 same shape, 2 disjoint)
  map_l1_paper       the same for FASTSIM's eq. 36 map against the exact
                     frictional power density D_I (CONTACT's FRIC_POWER)
  profile_l1         the same for the lateral work profiles (per strip)
  exact_power_in_fastsim_adhesion
                     share of the exact dissipation sum D_I that falls in
                     elements FASTSIM calls adhesion (its work there is 0)
  fastsim_work_in_exact_adhesion
                     share of FASTSIM's work in elements the exact theory
                     calls adhesion
  state_differences  elements in contact for both whose states differ
  centroid_fastsim, centroid_exact
                     work centroid along the rolling direction in units of
                     a (+1 leading edge, -1 trailing edge)

contact (defaults: the paper's Fig. 6 contact as fit-fig6 reproduces it --
a = 6.6323 mm, b = a/2, N = 10000 lbf, mu = 0.6, G = 82 GPa, nu = 0.3,
xi_x = 0.0019, xi_y = 0.0011, spin = 0.144 1/ft): --a --b --N --mu --G --nu
--xi-x --xi-y --spin --rolling-direction --spin-offset (both models; default
each model's own, 0 FASTSIM and 1/6 exact) --exact-load (the simplified
models) --tolerance --max-iterations (exact) --units si|paper (as for
solve). The exact model needs G and nu, and
the comparison is of the two theories as Kalker states them: --L1..--L3,
--pressure and --flexibility-blending are errors.
grid: uniform (--grid kalker_strips is an error), default 48 x 48 over 1.2 times the
semi-axes (40 elements across the ellipse, two guard cells on each side,
CONTACT's layout); --nx --ny (at most 256) --box-scale.
output: --format text|json|markdown (the summary on stdout; forces on the
wheel; markdown: one table row per simplified model, the distances and ratios
to exact, as doc/validation/fastsim-vs-exact.md shows them),
--out DIR, --force, --no-plots, --plot-axes normalised|physical
(--plot-sign changes nothing here: states and work have no sign).

files with --out (<label>: fastsim, fastsim_elliptic or calibrated):
  summary.json   units, <label>{}, exact{} (solve's JSON keys each),
                 metrics{}; with --simplified all one object per model and
                 metrics{<label>{}} for each
  totals.csv     one row per model: model,Fx_wheel_N,Fy_wheel_N,Mz_wheel_N_m,
                 W_macro_J_per_m,W_micro_paper_J_per_m,K,adhesion_fraction,
                 n_contact,n_adhesion,n_slip,p_max_Pa
  <label>/fields.csv <label>/profile.csv exact/fields.csv exact/profile.csv
                 each model's fields and lateral profile, as solve writes them
                 (every metric can be recomputed from them)
  compare.png    FASTSIM (left) beside exact (right): slip/adhesion maps,
                 energy-consistent work per unit area on one colour scale
                 (slip elements outlined), the lateral work profiles of both,
                 and the work-share difference FASTSIM minus exact
  slip_adhesion_<label>.png slip_adhesion_exact.png work_<label>.png
  work_exact.png work_difference.png profile.png, gnuplot/ (the scripts)
  work_maps.png  with --simplified all, instead of the above: the paper's
                 Fig. 6 for every model, energy-consistent work per unit area
                 side by side on one colour scale, adhesion light blue, slip
                 elements outlined, axes x/a and y/b

examples (the paper's Fig. 6 contact):
  creepwork compare --out fig6-compare
  creepwork compare --simplified all --out fig6-all
)";
}

const char* usage_wheelrail()
{
    return R"(usage: creepwork wheelrail --wheel-profile FILE --rail-profile FILE --Fz N [options]

One wheel on one rail, from the profiles to the forces (doc/wheelrail.md):
finds the contact patches of the wheelset position, the wheelset height at
which the vertical force on the rail is Fz, and per patch its position,
creepages and forces on the patch's undeformed distance grid (every patch
solved with its approach the rigid overlap at that height). Conventions are
CONTACT's module-1 ones: track coordinates x along the track, y to the right
seen along x, z down; patch frame x, s (lateral, in the tangent plane), n
(normal, into the rail); creepages of the rail relative to the wheel;
forces, tractions and moments on the rail. SI units.

profiles (the track and wheelset of the Manchester benchmark: gauge 1435 mm
measured 14 mm below the rail top, flange-back distance 1360 mm, flange back
at -70 mm, nominal wheel radius 460 mm, no extra cant):
  --wheel-profile FILE   SIMPACK .prw, MiniProf .whl, or a table of "y z"
  --rail-profile FILE    lines in mm (SIMPACK .prr, MiniProf .ban, table)
  --profile-unit M       metres per length unit of both files (default: a
                         file's own: SIMPACK its units, MiniProf and tables
                         mm; 1 for tables in metres)
  --wheel-y-offset M     added to the wheel profile's y [m]: its origin lies
                         on the tread with the flange back at -70 mm, so a
                         profile measured from the flange back (MiniProf)
                         takes --wheel-y-offset -0.07
  --mirror-wheel         the wheel profile's y is mirrored (measured with y
                         towards the track centre), before the offset
  --rail-y-offset M      added to the rail profile's y [m]

wheelset (defaults 0):
  --y-shift M            lateral shift [m]; the flange meets the rail within
                         about 10 mm (a warning above 20 mm)
  --yaw RAD              yaw angle [rad]
  --roll RAD             roll angle [rad]
  --V MPS                forward speed [m/s] (default 1)
  --pitch-rate RADPS     angular velocity about the axle [rad/s], < 0
                         rolling forward (default -V / 0.46 m)
  --side right|left      the wheel (default right)

contact:
  --Fz N                 vertical force on the rail [N] (required; --N is
                         the same option)
  --model exact|fastsim  exact (default): Kalker's exact theory with the
                         exact normal problem, as CONTACT's module 1;
                         fastsim (or fast): FASTSIM with the semi-Hertzian
                         normal problem (doc/validation/manchester.md: its
                         accuracy)
  --mu MU                friction coefficient (default 0.3); with a law, its
                         kinetic coefficient mu_kin
  --friction-law coulomb|linear|rational|exponential|polach
                         a law of the slip speed in every patch (--model
                         exact; as creepwork solve's, doc/theory/friction.md):
                         an element's slip speed is its micro-slip times the
                         patch's rolling speed veloc
  --mu-e1 M --s-h1 S --mu-e2 M --s-h2 S
                         the law's falling terms [-] and half speeds [m/s]
  --polach-A A --polach-B B
                         --friction-law polach: Polach's A [-] and B [s/m],
                         with --mu as mu0
  --memory-distance D --memory-s0 S
                         friction memory with a law (as creepwork solve's):
                         its slip distance [m] and background slip speed
                         [m/s] (default 0: none)
  --layer-h H --layer-G G3
                         an interface layer's thickness [m] and shear
                         modulus [Pa] in every patch (--model exact; default
                         0: none)
  --tau-c0 T             the layer's yield stress [Pa]; a patch's grid is a
                         gap grid, where the exact model refuses the yield
  --G PA                 combined shear modulus [Pa] (default 8.2e10)
  --nu NU                combined Poisson's ratio (default 0.28)
  --dx M, --ds M         element sizes of the patch grids [m] (default 2e-4)

surface temperature (degC; body 1 the rail, body 2 the wheel):
  --temperature          also each patch's hottest rail and wheel element
                         (JSON: T_max_1, T_max_2 per patch), at the patch's
                         rolling speed (veloc) and direction
  --T0-1 T --T0-2 T, --heat-capacity-1/-2, --conductivity-1/-2,
  --density-1/-2, --temperature-discretisation consistent|contact
                         as creepwork solve (steel by default)

Warnings (stderr, exit 0) name inputs in a wrong unit and placements no
running wheel has: a patch on the wheel's flange tip, a wheelset lifted or
lowered by more than 5 mm on a tread contact, a wheel profile whose flange
tip lies on the field side of its origin -- each with its likely cause.

output (--format text, the default, or json): the model, the wheelset
height z_ws [m] (> 0 lowers the wheelset) and per patch K = 0, 1, ..., from
the field side to the track centre: y_contact_rail, z_contact_rail (the
contact reference point on the rail profile) [m], contact_angle [rad], the
creepages cksi, ceta [-] and cphi [1/m] of the rail relative to the wheel
(CONTACT's CKSI, CETA, CPHI), Fn [N], Fx_rail, Fs_rail [N] and Mn_rail [N m]
on the rail in the patch frame, p_max [Pa], n_contact, n_adhesion, n_slip
(elements); JSON: "model" (exact or fastsim), "sign_convention", and per
patch also x_contact, y_contact, z_contact (track), y_contact_wheel,
z_contact_wheel, veloc, approach, rolling_radius and the patch force on the
rail in track coordinates Fx_track, Fy_track, Fz_track; total_rail holds Fx,
Fy, Fz on the rail in track coordinates (doc/reference/conventions.md: every
key's sign and body). creepwork's own convention (forces on the wheel) is
xi_x = -cksi, xi_y = ceta, phi = cphi, Fx = -Fx_rail, Fy = Fs_rail,
Mz = Mn_rail.

  --out DIR              also write DIR/result.json (the JSON above),
                         profiles.csv (body,y_m,z_m: the rail's and the
                         wheel's profile points in track coordinates at the
                         solved position), per patch K = 0, 1, ...
                         patch_K_fields.csv (x_m,s_m,area_m2,pz_Pa,px_Pa,
                         ps_Pa,sx,ss,state,work_J_per_m: one row per element,
                         x fastest, x and s from the reference point,
                         tractions on the rail, micro-slips of the rail,
                         state 0 exterior, 1 adhesion, 2 slip, the
                         energy-consistent work per rolled distance) and,
                         with gnuplot on PATH, profiles.png (the profiles,
                         contact points, normals and forces on the rail) and
                         patch_K.png (pressure, slip/adhesion, tractions on
                         the rail along x and s, work per unit area over x,
                         s); scripts and data in DIR/gnuplot/
  --force                replace an earlier --out DIR of creepwork's
  --no-plots             data files only

example (the Manchester benchmark, case A-2.2 at 3 mm):
  creepwork wheelrail --wheel-profile MBench_S1002_v3.prw \
      --rail-profile MBench_UIC60_v3.prr --y-shift 3e-3 --yaw 0.0072 \
      --roll -1.803e-4 --Fz 1e4 --V 2 --pitch-rate -4.3451503 --format json
)";
}

const char* usage_transient()
{
    return R"(usage: creepwork transient --steps STEPS.csv --gap GAP.csv (--N N | --approach A)
                          [options]
       creepwork transient --steps STEPS.csv --a A --b B --N N [--nx NX --ny NY
                          --box-scale S] [options]

Transient rolling (doc/theory/transient.md): Kalker's exact theory with
memory on the gap grid of GAP.csv (the file of creepwork solve --gap), in
contact-fixed coordinates: the material moves through the contact from +x
(the leading edge) by dq per step, and the tractions of each step start from
those of the last. Every step is committed. SI units throughout. With
--coordinates world the grid stays with the material and the geometry moves
over it by dq towards +x per step (the grid must hold the contact over the
run).

STEPS.csv: a header naming the columns, then one step per line ('#' lines
and blank lines are skipped):
  dq_m           distance rolled in the step [m], 0 <= dq_m <= the gap
                 grid's dx; 0 is a shift (Cattaneo's problem)     required
  xi_x, xi_y     creepages [-]; with dq_m = 0 the rigid shift [m] default 0
  phi            spin [1/m]; with dq_m = 0 the rotation [rad]      default 0
With --prescribe forces:
  Fx             the longitudinal force on the wheel [N]: xi_x is found
  Fy             the lateral force [N]: xi_y is found (or give xi_y)

options:
  --steps FILE        the steps (required)
  --gap FILE          the contact's gap: header x_m,y_m,h_m, or
  --a A, --b B        an elliptic (Hertzian) contact's semi-axes [m] on the
                      exact model's uniform grid --nx, --ny, --box-scale
                      (as creepwork solve --model exact --grid uniform)
  --N N               normal force [N], or
  --approach A        the approach [m] from the gap's datum
  --model M           exact (default: Kalker's exact theory) or fastsim
                      (FASTSIM's transient form, doc/theory/transient.md)
  --normal-method M   exact (default) or semi_hertz
  --G, --nu, --mu     shear modulus [Pa], Poisson's ratio, friction
                      (default steel 82e9, 0.28; mu 0.3)
  --tolerance T, --max-iterations K, --spin-offset S
                      as for creepwork solve --model exact
  --prescribe P       creepages (default) or forces
  --coordinates C     contact (default: contact-fixed, CONTACT's T = 2) or
                      world (world-fixed, T = 1: the normal problem per step)
  --start S           zero (default: zero tractions) or steady (the steady
                      rolling solution of the first line's creepages or
                      forces, then every line as a step)
  --format F          text (default: one line per step) or json: a list
                      with one object per step: line xi_x xi_y phi Fx Fy Mz
                      n_contact n_adhesion n_slip W_step W_slip
                      iterations
  --out DIR           also write DIR/history.csv (every step's numbers,
                      round-trip) and pictures: step_NNN.png per step (the
                      slip/adhesion state, both tractions, p_x along the
                      centre row with its bound +-mu p_z; at most 100 steps
                      drawn, spread evenly, the last always) and
                      history.png (the creepages and forces over the steps);
                      their gnuplot scripts and data in DIR/gnuplot
  --force             replace an earlier output of creepwork in DIR
  --no-plots          data files only

Outputs: xi_x, xi_y, phi as given or found; Fx, Fy, Mz on the wheel [N, N,
N m], Mz about the gap file's origin; W_step the frictional work of the
step [J], energy-consistent (in steady rolling dq times the steady model's
W_macro); W_slip the dissipation of the step's own slip [J] (CONTACT's
frictional work): the slip weighted by the new traction, below W_step in
steady rolling, 2 W_step at a shift from rest.
)";
}

} // namespace cwcli
