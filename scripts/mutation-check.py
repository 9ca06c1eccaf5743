#!/usr/bin/env python3
"""Mutation check: do the tests catch deliberate single-line bugs?

Part of the development routine (CONTRIBUTING.md), not of CI: it builds a copy of
the working tree, then for each mutant below applies one single-line edit,
rebuilds only the executables of the tests that could catch it, runs those
tests and records which failed. Every mutant must be caught by at least two
tests; a mutant of a model may further name tests that must be among its
catchers (the exact and calibrated models' bugs must be caught by CONTACT's
reference data, not by tests that reuse the model's own formulas).

    scripts/mutation-check.py [--only ID ...] [--jobs N] [--keep] [--all-tests]

Prints a Markdown table (mutant, edit, tests that caught it, candidates that
did not) and exits 1 when a mutant is caught by fewer than two tests, misses
a required catcher, fails to apply or fails to compile. The working tree is
never touched: the copy lives in a temporary directory (--keep keeps it).
Cost: one Release build of the copy (a few minutes on 2 cores), then per
mutant one recompiled file, a few relinks and its candidate tests (~15-30 s).
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

# Tests that check the FASTSIM core against data or formulas from outside the
# code (CONTACT's rows, the FORTRAN 77 reference, Kalker's published values,
# hand computations), plus the wiring checks that read the same quantities.
CORE = [
    "test_core_contact_reference", "test_core_coefficients", "test_core_linear_theory",
    "test_core_full_slip", "test_core_symmetry", "test_core_convergence", "test_core_work",
    "test_core_kernels", "test_fortran_sweep", "test_fortran_kalker1982", "test_capi_solver",
    "cli_fit_fig6_reproduces_the_paper",
]

# Wear: the tests that check it against closed forms, published values and
# the C ABI, the Fortran layers and the CLI.
WEAR = [
    "test_core_wear", "test_capi_wear", "test_fortran_wear", "cli_wear_matches_library",
    "cli_wear_wheel_distance", "example_wear_loop_f77", "example_c_wear_quickstart",
]

# The exact model: CONTACT's rows (test_core_exact_reference, its 100 x 100
# entry), the model's own properties, the C ABI and Fortran doors.
EXACT = [
    "test_core_exact_reference", "test_core_exact_reference_100", "test_core_exact_model",
    "test_core_exact_energy", "test_core_exact_jacobian", "test_capi_exact", "test_fortran_exact",
]
# Results that must not depend on what a handle solved before: cold solves
# (warm_start = 0) and batches (cold by construction).
COLD = [
    "test_core_exact_model", "test_capi_exact", "test_robustness_determinism", "test_capi_batch",
    "test_capi_threads",
]
# The warm start's prediction: the history's polynomial paths, a warm drift's
# products on the ellipse and on a gap patch, the warm = cold checks.
WARM = [
    "test_core_exact_parts", "test_core_exact_model", "test_nonhertz_model", "test_capi_exact",
]
# The calibrated model: its linear limit (Kalker's coefficients), accuracy
# against the exact model's continuum estimate, its Jacobian against
# central differences, the C ABI and the CLI.
CALIBRATED = [
    "test_core_calibrated", "test_core_calibrated_jacobian", "test_capi_calibrated",
    "test_capi_jacobian", "cli_solve_calibrated_matches_library",
]
# The C ABI's versioned structs (struct_size): growth, errors, batches.
ABI = [
    "test_capi_abi_growth", "test_capi_batch", "test_capi_errors", "test_capi_solver",
    "test_capi_wear", "test_capi_accumulator", "test_robustness_validation",
]

# One entry per mutant: file, the exact text of one line (or a unique part of
# it) and its replacement, the candidate tests, and tests that must be among
# the catchers ("require"): the exact and calibrated models' bugs must be
# caught by data from outside the model (CONTACT's rows, Kalker's
# coefficients, the exact theory), never only by tests that recompute the
# model's own formulas.
MUTANTS = [
    dict(id="moment-sign", what="creep moment Mz reported with the wrong sign",
         file="core/march/march_model.cpp",
         old="    t.Mz = d * mz;", new="    t.Mz = -d * mz;", tests=CORE),
    dict(id="moment-arm", what="sign of the y px term of Mz (moment about the centre)",
         file="core/march/march.cpp",
         old="Phi[2] += area * (a * march.sum_x_py[j] - y * march.sum_px[j]);",
         new="Phi[2] += area * (a * march.sum_x_py[j] + y * march.sum_px[j]);", tests=CORE),
    dict(id="half-first-step", what="Kalker's strips start with a full step, not half a step",
         file="core/contact/contact_grid.cpp",
         old="        double previous = half_chord;",
         new="        double previous = half_chord + 0.5 * dx;", tests=CORE),
    dict(id="numerical-dissipation", what="numerical dissipation 1/2 dp L dp doubled",
         file="core/march/march_work.cpp",
         old="loss += half_T * (TL1 * dpx * dpx + TL2 * dpy * dpy) * dy;",
         new="loss += T * (TL1 * dpx * dpx + TL2 * dpy * dpy) * dy;", tests=CORE),
    dict(id="friction-dissipation", what="friction dissipation factor f (1 - f) -> (1 - f^2)",
         file="core/march/march_work.cpp",
         old="d = slip ? T * f * (one - f) *", new="d = slip ? T * (one - f * f) *", tests=CORE),
    dict(id="spin-rigid-slip", what="spin term of the lateral rigid slip negated (eq. 12 misprint)",
         file="core/march/march_setup.cpp",
         old="s.a * s.a * s.phi / s.L3};", new="-s.a * s.a * s.phi / s.L3};", tests=CORE),
    dict(id="traction-bound", what="slip only 1 % beyond the traction bound mu pz",
         file="core/contact/friction_law.hpp",
         old="    const auto slip = norm > bound;",
         new="    const auto slip = norm > bound * simd::broadcast<W>(1.01);",
         tests=CORE + ["test_core_friction_law"], require=["test_core_friction_law"]),
    # The friction-law hook's projection derivative (contact/friction_law.hpp):
    # its test against differences, and the Jacobians that use it.
    dict(id="projection-derivative-factor", what="the slip derivative drops the factor f",
         file="core/contact/friction_law.hpp", old="    dpx = s.f * dqx - c * s.px;",
         new="    dpx = dqx - c * s.px;",
         tests=["test_core_friction_law", "test_core_jacobian", "test_capi_jacobian"],
         require=["test_core_friction_law", "test_core_jacobian"]),
    dict(id="projection-derivative-bound", what="the bound's own change enters with the wrong sign",
         file="core/contact/friction_law.hpp",
         old="    const simd::Vec<W> cb = r * (s.px * dqx + s.py * dqy) - dbound_over_bound;",
         new="    const simd::Vec<W> cb = r * (s.px * dqx + s.py * dqy) + dbound_over_bound;",
         tests=["test_core_friction_law"] + CALIBRATED,
         require=["test_core_friction_law", "test_core_calibrated_jacobian"]),
    dict(id="eq36-moment-arm", what="paper's work: spin slip at the slip point, not the element",
         file="core/march/march_work.cpp",
         old="- spin_y * xp + phi * xc))", new="- spin_y * xp + phi * xp))", tests=CORE),
    dict(id="prints", what="solve prints a debugging line",
         file="capi/capi_solver.cpp",
         old="        const cw::SolveTotals& t = solver->solver.solve(in, m);",
         new="        const cw::SolveTotals& t = solver->solver.solve(in, m); __builtin_printf(\"K %g\\n\", t.K);",
         tests=["test_robustness_silent", "test_capi_solver", "cli_json_matches_library"],
         min_caught=1),  # only the silent test can see output: one catcher is all there is
    # Wear: the laws, the depth of a pass, the remap, the exact sums and the
    # update helper, against closed forms and published values.
    dict(id="usfd-plateau-end", what="USFD's severe plateau ends before 77.2 N/mm^2",
         file="core/wear/wear_law.hpp", old="    if (t <= c.t2) {", new="    if (t < c.t2) {",
         tests=WEAR),
    dict(id="wear-depth-width", what="depth per pass divided by the semi-axis, not the strip width",
         file="core/wear/wear_map.cpp",
         old="const double to_depth = quotient_if_positive(1.0, rho * dy);",
         new="const double to_depth = quotient_if_positive(1.0, rho * in.b);", tests=WEAR),
    dict(id="wear-archard-sliding", what="Archard's sliding taken as T/A instead of T/(A |p|)",
         file="core/wear/wear_map.cpp",
         old="s = quotient_if_positive(tga, magnitude(px, py));", new="s = tga;", tests=WEAR),
    dict(id="remap-height", what="height depth multiplied by cos(gamma) instead of divided",
         file="core/wear/wear_profile.cpp",
         old="height_[k].add_product(passes, c / cosg);",
         new="height_[k].add_product(passes, c * cosg);", tests=WEAR),
    dict(id="exact-top-word", what="the exact accumulator drops a product's third word",
         file="core/wear/exact_sum.cpp", old="    parts[2] = r ? hi >> (64 - r) : 0;",
         new="    parts[2] = 0;", tests=WEAR),
    dict(id="smoothing-volume", what="the update's smoothing forgets the source cell's width",
         file="core/wear/wear_profile.cpp",
         old="coef[m] = depth[m] * widths[m] / Z;", new="coef[m] = depth[m] * widths[0] / Z;",
         tests=WEAR),
    # The KTH map's boundaries, each approached from both sides
    # (test_core_wear, and test_capi_wear on an element's own velocity).
    dict(id="kth-slow-closed", what="KTH: v = v1 counted as slow, not severe",
         file="core/wear/wear_law.hpp", old="    if (v < m.v1) {", new="    if (v <= m.v1) {",
         tests=WEAR),
    dict(id="kth-severe-open", what="KTH: v = v2 counted as fast, not severe",
         file="core/wear/wear_law.hpp", old="    if (v <= m.v2) {", new="    if (v < m.v2) {",
         tests=WEAR),
    dict(id="kth-seizure-closed", what="KTH: seizure already at p = ratio H",
         file="core/wear/wear_law.hpp", old="    if (p > m.seizure_ratio * m.hardness) {",
         new="    if (p >= m.seizure_ratio * m.hardness) {", tests=WEAR),
    # The exact model.
    dict(id="exact-spin-offset", what="exact: CONTACT's default facphi 1/6 forgotten (the rows "
         "give theirs)", file="core/exact/exact_model.hpp",
         old="kExactDefaultSpinOffset = 1.0 / 6.0;", new="kExactDefaultSpinOffset = 0.0;",
         tests=EXACT),
    dict(id="exact-spin-slip", what="exact: the spin term of the lateral rigid slip negated",
         file="core/exact/exact_model.cpp",
         old="setup_.c_eta + cphi * (L.geom.X(i) + setup_.spin_offset)};",
         new="setup_.c_eta - cphi * (L.geom.X(i) + setup_.spin_offset)};", tests=EXACT,
         require=["test_core_exact_reference"]),
    dict(id="exact-moment-arm", what="exact: sign of the y px term of Mz",
         file="core/exact/exact_model.cpp", old="mz += x * q[k].imag() - y * q[k].real();",
         new="mz += x * q[k].imag() + y * q[k].real();", tests=EXACT,
         require=["test_core_exact_reference"]),
    dict(id="exact-cold-normal", what="exact: a cold solve starts its normal problem from the "
         "last pressure", file="core/exact/exact_model.cpp",
         old="    const bool start = warm && L.normal_valid;",
         new="    const bool start = L.normal_valid;", tests=COLD),
    dict(id="exact-cold-reuse", what="exact: a cold solve reuses a warm-started normal solution",
         file="core/exact/exact_model.cpp", old="(warm || L.normal_cold))",
         new="(warm || true))", tests=COLD),
    # The warm start's prediction (core/exact/creepage_history.cpp): the secant
    # step's error extrapolated along a drift. Caught by the history's own
    # polynomial paths and by the products of a warm drift's steps.
    dict(id="warm-error-constant", what="exact: the warm start adds the last error, not its "
         "linear extrapolation", file="core/exact/creepage_history.cpp",
         old="            v += 2.0 * error_[k] - error_before_[k];",
         new="            v += error_[k];", tests=WARM),
    dict(id="warm-error-not-kept", what="exact: the warm start extrapolates from an error never "
         "kept (zero)", file="core/exact/creepage_history.cpp",
         old="    error_before_.swap(error_);", new="    error_before_.swap(error_before_);",
         tests=WARM),
    # Warm GMRES's Gram-Schmidt in partial sums (core/exact/steady_rolling.cpp,
    # subtract_dot): wrong inner products or basis vectors cost a warm drift
    # its products (or its convergence, retried cold).
    dict(id="warm-gmres-partial-sums", what="exact: warm GMRES's inner products drop half "
         "their partial sums", file="core/exact/steady_rolling.cpp",
         old="    for (int k = L / 2; k >= 1; k /= 2) // pairwise: (s0 + s1) + (s2 + s3)",
         new="    for (int k = L / 2; k > 1; k /= 2) // pairwise: (s0 + s1) + (s2 + s3)",
         tests=WARM),
    dict(id="warm-gmres-operator-sign", what="exact: warm GMRES applies G' - I, not I - G'",
         file="core/exact/steady_rolling.cpp",
         old="                const V r = apply ? bv - av : av - hv * bv;",
         new="                const V r = apply ? av - bv : av - hv * bv;",
         tests=WARM),
    dict(id="warm-gmres-normalise", what="exact: warm GMRES's basis vector not normalised",
         file="core/exact/steady_rolling.cpp",
         old="                for (int t = 0; t < n_; ++t) v[t] *= 1.0 / h;",
         new="                for (int t = 0; t < n_; ++t) v[t] *= 1.0;", tests=WARM),
    # The warm Newton steps' coarse correction (core/exact/coarse_correction.cpp):
    # a wrong coarse space or Galerkin operator costs a warm drift its products;
    # the space is checked against the FFT products, the operator by M K P = P.
    dict(id="coarse-kernel-shift", what="exact: the coarse space's rolling kernel (B P's "
         "updates) negated, A(d + e_x) - A(d)", file="core/exact/coarse_correction.cpp",
         old="                for (int m = 0; m < wx; ++m) k[m] = a[m] - a[m + 1];",
         new="                for (int m = 0; m < wx; ++m) k[m] = a[m + 1] - a[m];",
         tests=WARM + ["test_nonhertz_parts"]),
    dict(id="coarse-run-sums-sign", what="exact: the rolling kernel's sums along x negated "
         "(B P's runs)", file="core/exact/coarse_correction.cpp",
         old="                for (size_t m = 0; m < wp; ++m) a[m] = first - a[m];",
         new="                for (size_t m = 0; m < wp; ++m) a[m] = a[m] - first;",
         tests=WARM + ["test_nonhertz_parts"]),
    dict(id="coarse-run-short", what="exact: a run of B P's sources drops its last element",
         file="core/exact/coarse_correction.cpp",
         old="        const size_t hi = row + nx_ - i0, lo = row + nx_ - 1 - i1;",
         new="        const size_t hi = row + nx_ - i0, lo = row + nx_ - i1;",
         tests=WARM + ["test_nonhertz_parts"]),
    # The cold solve's coarse correction (core/exact/steady_rolling.cpp): made
    # afresh for each cold solve (a fresh handle's bits), and on in partial slip.
    dict(id="cold-coarse-kept", what="exact: a cold solve keeps the last solve's coarse "
         "correction", file="core/exact/steady_rolling.cpp",
         old="    if (!warm) coarse_.forget();", new="    if (!warm) (void)0;",
         tests=WARM + ["test_robustness_determinism", "test_nonhertz_capi"]),
    dict(id="cold-coarse-off", what="exact: a cold solve never runs with the coarse correction",
         file="core/exact/steady_rolling.cpp",
         old="adhesion_share() >= kColdAdhesion)) {", new="adhesion_share() > 1.0)) {",
         tests=WARM),
    dict(id="coarse-update-sign", what="exact: an element leaving the contact set is added "
         "to its block's B P, not taken out", file="core/exact/coarse_correction.cpp",
         old="        add_element(k, a, in ? 1.0 : -1.0);",
         new="        add_element(k, a, 1.0);", tests=WARM + ["test_nonhertz_parts"]),
    dict(id="coarse-galerkin-identity", what="exact: the Galerkin operator drops P^T P "
         "(T = -P^T G' P)", file="core/exact/coarse_correction.cpp",
         old="        t_[static_cast<size_t>(c) * m + c] += size_[c / 2];",
         new="        t_[static_cast<size_t>(c) * m + c] += 0.0;", tests=WARM),
    dict(id="coarse-solution-unpreconditioned", what="exact: warm GMRES adds V y to the "
         "solution, not M V y", file="core/exact/steady_rolling.cpp",
         old="            for (int t = 0; t < n_; ++t) x[t] += pre_[t];",
         new="            for (int t = 0; t < n_; ++t) x[t] += pre2_[t];", tests=WARM),
    # The calibrated model.
    dict(id="calibrated-moment-flexibility", what="calibrated: spin x-slip on L3/L_M, not L_M/L3",
         file="core/calibrated/calibrated_model.cpp", old="        s.kin.cx *= s.L3 / L_M;",
         new="        s.kin.cx *= L_M / s.L3;", tests=CALIBRATED, require=["test_core_calibrated"]),
    dict(id="calibrated-blend-shape", what="calibrated: blended bound 0.7 sqrt(P), N not carried",
         file="core/calibrated/blended_bound.cpp", old="ce = blend * 0.75;",
         new="ce = blend * 0.7;", tests=CALIBRATED, require=["test_core_calibrated"]),
    dict(id="calibrated-blend-derivative", what="calibrated Jacobian: d(bound)/d(blend) sign of P",
         file="core/calibrated/march_directional.cpp", old="(three_quarters * E - P)",
         new="(three_quarters * E + P)", tests=CALIBRATED,
         require=["test_core_calibrated_jacobian"]),
    # The C ABI's struct_size checks.
    dict(id="abi-size-floor", what="struct_size smaller than the size field accepted",
         file="capi/capi_internal.hpp",
         old="    return size >= sizeof(size_t) && size <= kMaxStructSize;",
         new="    return size >= 1 && size <= kMaxStructSize;", tests=ABI),
    dict(id="abi-read-past-size", what="a params struct read past its struct_size",
         file="capi/capi_internal.hpp",
         old="    std::memcpy(&value, caller, std::min(size, sizeof(T)));",
         new="    std::memcpy(&value, caller, sizeof(T));", tests=ABI),
    dict(id="abi-write-past-size", what="a result struct written past its struct_size",
         file="capi/capi_internal.hpp",
         old="    std::memcpy(caller, &copy, std::min(size, sizeof(T)));",
         new="    std::memcpy(caller, &copy, sizeof(T));", tests=ABI),
]


# ---------------------------------------------------------------------------
# Fortran wrappers (issues 22, 26): module creepwork (fortran/creepwork_*.f90)
# and the legacy layer (fortran/creepwork_legacy*.f90, legacy_thread_state.cpp).
# Kept apart from the core's mutants above so that both lists can change
# independently. The catchers compare against the C ABI bit for bit
# (test_fortran_cross, test_fortran_legacy_threads), against published or
# closed-form values, or check the message and the status.
FORTRAN = [
    "test_fortran_api", "test_fortran_sweep", "test_fortran_cross", "test_fortran_wear",
    "test_fortran_exact", "test_fortran_jacobian", "test_fortran_exact_load",
    "test_fortran_error_stop_invalid", "test_fortran_legacy_f77", "test_fortran_legacy_exact",
    "test_fortran_legacy_last", "test_fortran_legacy_threads", "test_fortran_kalker1982",
    "example_wear_loop_f77",
]

FORTRAN_MUTANTS = [
    dict(id="f-size-minus-one", what="a wrapper passes size(out) - 1 as the buffer length",
         file="fortran/creepwork_wear.f90",
         old="handle_of(self), int(kind, c_int), out, size(out, kind=c_size_t)))",
         new="handle_of(self), int(kind, c_int), out, size(out, kind=c_size_t) - 1))",
         tests=FORTRAN),
    dict(id="f-message-detail", what="errmsg keeps the static text, drops the detail naming the input",
         file="fortran/creepwork_handle.f90",
         old="            o%message = head//': '//detail", new="            o%message = head",
         tests=FORTRAN),
    dict(id="f-result-dropped", what="solve passes NULL for the caller's result",
         file="fortran/creepwork_solver.f90",
         old="                                 result_pointer(result)))",
         new="                                 c_null_ptr))", tests=FORTRAN),
    dict(id="f-swapped-creepages", what="legacy entries swap XI and ETA (dummy order)",
         file="fortran/creepwork_legacy_support.f90",
         old="function material_params(a, b, fn, fmu, g, pnu, xi, eta, phi) result(p)",
         new="function material_params(a, b, fn, fmu, g, pnu, eta, xi, phi) result(p)",
         tests=FORTRAN),
    dict(id="f-swapped-normalised", what="the normalised FASTSIM wrapper swaps UX and UY",
         file="fortran/creepwork_functions.f90",
         old="capi_fastsim_normalised(ux, uy, fx, fy, int(mx, c_int), int(my, c_int), &",
         new="capi_fastsim_normalised(uy, ux, fx, fy, int(mx, c_int), int(my, c_int), &",
         tests=FORTRAN),
    dict(id="f-load-dropped", what="CWFORC ignores LOAD (exact_load)",
         file="fortran/creepwork_legacy.f90",
         old="   p%exact_load = LOAD", new="   p%exact_load = 0", tests=FORTRAN),
    dict(id="f-cache-key", what="CWFORC's solver cache ignores ny in the grid shape",
         file="fortran/legacy_thread_state.cpp",
         old="return a.kind == b.kind && a.nx == b.nx && a.ny == b.ny &&",
         new="return a.kind == b.kind && a.nx == b.nx &&", tests=FORTRAN),
    dict(id="f-cwlast-padding", what="CWLAST leaves MSG unpadded after the message",
         file="fortran/creepwork_legacy_tools.f90",
         old="   if (n < len(MSG)) MSG(n + 1:) = ' '", new="   continue", tests=FORTRAN),
    # CWFMEM: against module creepwork bit for bit and against closed forms.
    dict(id="f-cwfmem-memory", what="CWFMEM drops the memory's slip distance",
         file="fortran/creepwork_legacy_friction.f90",
         old="   p%memory_distance = DC", new="   p%memory_distance = 0",
         tests=["test_fortran_legacy_friction", "test_fortran_legacy_memory"],
         require=["test_fortran_legacy_friction", "test_fortran_legacy_memory"]),
    dict(id="f-cwfmem-layer", what="CWFMEM drops the layer's thickness",
         file="fortran/creepwork_legacy_friction.f90",
         old="   p%layer_h = HL", new="   p%layer_h = 0",
         tests=["test_fortran_legacy_friction", "test_fortran_legacy_memory"],
         require=["test_fortran_legacy_friction", "test_fortran_legacy_memory"]),
]
MUTANTS = MUTANTS + FORTRAN_MUTANTS


# ---------------------------------------------------------------- campaign
# The campaign's chunk planner (which rows a chunk holds, on a fresh run and
# on a resume) and results writer (results.csv from the checkpoint's chunks):
# caught by the unit tests of the parts and by campaigns run through mpirun.
CAMPAIGN = [
    "campaign_unit_chunk_planner_covers_each_row_once",
    "campaign_unit_results_writer_puts_rows_in_order", "campaign_ranks_and_threads_bitwise",
    "campaign_bad_rows_get_error_lines", "campaign_resume_with_one_row_pending",
    "campaign_unit_mistakes_are_warned", "campaign_schema_defaults_and_aliases",
    "campaign_wear_ranks_bitwise",
]
CAMPAIGN_MUTANTS = [
    dict(id="planner-single-row", what="a pending range of one row is dropped (resume of one row)",
         file="programs/campaign/chunk_planner.cpp",
         old="[](const auto& r) { return r.second <= r.first; }),",
         new="[](const auto& r) { return r.second <= r.first + 1; }),", tests=CAMPAIGN),
    dict(id="planner-range-end", what="a chunk runs one row past its pending range",
         file="programs/campaign/chunk_planner.cpp",
         old="    count = std::min(count, end - cursor_);",
         new="    count = std::min(count, end - cursor_ + 1);", tests=CAMPAIGN),
    dict(id="planner-last-row", what="the last row of the input is never pending",
         file="programs/campaign/chunk_planner.cpp",
         old="        while (j < n && !done[j]) ++j;",
         new="        while (j + 1 < n && !done[j]) ++j;", tests=CAMPAIGN),
    dict(id="writer-order", what="results.csv takes the chunks in reverse order",
         file="programs/campaign/results_writer.cpp",
         old="                  return x.first_row < y.first_row;",
         new="                  return x.first_row > y.first_row;", tests=CAMPAIGN),
    dict(id="writer-failed-numbers", what="numbers written for rows the library or --strict refused",
         file="programs/campaign/results_writer.cpp",
         old="            if (o.status != CW_OK) continue;",
         new="            if (o.status == kStatusRowUnreadable) continue;", tests=CAMPAIGN),
    dict(id="writer-id-quoting", what="an id with a comma is written unquoted",
         file="programs/campaign/results_writer.cpp",
         old='        line = csv_quote(in.ids[row]) + "," + status_name(o.status);',
         new='        line = in.ids[row] + "," + status_name(o.status);', tests=CAMPAIGN),
    dict(id="writer-warnings", what="a solved row's warnings are not written to its message",
         file="programs/campaign/results_writer.cpp",
         old="        const std::string& message = o.status == CW_OK ? in.warnings[row] : o.message;",
         new="        const std::string& message = o.message;", tests=CAMPAIGN),
    dict(id="writer-counts", what="rows the library refused counted as solved",
         file="programs/campaign/results_writer.cpp",
         old="        if (o.status == CW_OK) {",
         new="        if (o.status >= CW_OK) {", tests=CAMPAIGN),
]
# Temperature and damage columns (--temperature, --mu-T, --k-yield): caught
# by the columns against `creepwork solve`'s JSON, with and without mu(T).
CAMPAIGN_SURFACE = ["campaign_surface_matches_creepwork_solve",
                    "campaign_surface_mu_T_matches_creepwork_solve"]
CAMPAIGN_MUTANTS += [
    dict(id="campaign-surface-body", what="T_max_2 holds the rail's (body 1's) maximum",
         file="programs/campaign/row_solver.cpp",
         old="        out.surface[kSurfaceTMax2] = t.T_max_2;",
         new="        out.surface[kSurfaceTMax2] = t.T_max_1;", tests=CAMPAIGN_SURFACE),
    dict(id="campaign-surface-column", what="the FI_surf column holds the RCF index",
         file="programs/campaign/results_writer.cpp",
         old='    {"FI_surf", kSurfaceFISurf, &ResultColumns::damage},',
         new='    {"FI_surf", kSurfaceRcfIndexMax, &ResultColumns::damage},',
         tests=CAMPAIGN_SURFACE),
    dict(id="campaign-surface-wire", what="a row's temperature and damage are lost in the checkpoint",
         file="programs/campaign/wire.cpp",
         old="        o.surface = r.get_doubles();",
         new="        r.get_doubles();", tests=CAMPAIGN_SURFACE),
]
MUTANTS += CAMPAIGN_MUTANTS
# ------------------------------------------------------------ end campaign

# ------------------------------------------------------ contacts of any shape
# The gap model (core/gap/gap_exact_model.cpp), its patches and the fast normal
# method: caught by CONTACT's rows on gap grids (test_nonhertz_contact), the
# Hertzian gap against the elliptic model and the patch sums, and the doors.
GAP = [
    "test_nonhertz_contact", "test_nonhertz_model", "test_nonhertz_capi", "test_nonhertz_fast",
    "test_nonhertz_parts", "test_fortran_gap", "cli_gap_json_matches_library",
    "test_nonhertz_fastsim",
]
GAP_MUTANTS = [
    dict(id="gap-spin-slip", what="the gap model's rigid slip takes +phi y along x",
         file="core/gap/gap_exact_model.cpp",
         old="            w[i + L.nx * j] = {s.xi - s.phi * y, s.eta + s.phi * (x + s.spin_offset * L.dx)};",
         new="            w[i + L.nx * j] = {s.xi + s.phi * y, s.eta + s.phi * (x + s.spin_offset * L.dx)};",
         tests=GAP, require=["test_nonhertz_contact"]),
    dict(id="gap-patch-force", what="a patch's normal force sums pressures without the area",
         file="core/gap/gap_exact_model.cpp",
         old="            P.Fn += pressure[k] * area;",
         new="            P.Fn += pressure[k];", tests=GAP),
    dict(id="patches-no-up-neighbour", what="patch labels never join runs of neighbouring rows",
         file="core/normal/patches.cpp",
         old="                if (ra != rb) parent_[std::max(ra, rb)] = std::min(ra, rb);",
         new="                if (ra != rb && false) parent_[std::max(ra, rb)] = std::min(ra, rb);",
         tests=GAP),
    dict(id="semi-hertz-pressure", what="the semi-Hertzian peak pressure grows with the depth, not its root",
         file="core/normal/semi_hertz.cpp",
         old="        for (int e = 0; e < n; ++e) v[e] = std::sqrt(std::max(v[e], 0.0));",
         new="        for (int e = 0; e < n; ++e) v[e] = std::max(v[e], 0.0);", tests=GAP),
    dict(id="semi-hertz-mirror-once", what="a semi-Hertzian row's roots count once, not on both sides",
         file="core/normal/semi_hertz.cpp",
         old="                wr[m] = m >= 1 && m <= both ? two : pf;",
         new="                wr[m] = pf;", tests=GAP),
    # FASTSIM on a gap grid: caught by the exact model on the 26 shapes
    # (test_nonhertz_fastsim), the elliptic FASTSIM on a shifted Hertzian gap
    # and the hand-computed adhesion limit per patch (test_nonhertz_capi).
    dict(id="gap-fastsim-segment-count", what="a gap FASTSIM segment counts one element short",
         file="core/gap/gap_march.cpp",
         old="        t.n_contact += first - last + 1;",
         new="        t.n_contact += first - last;", tests=GAP),
    dict(id="gap-fastsim-stale-pressure", what="after the exact normal problem the semi-Hertzian "
         "method clears only its own last extents", file="core/normal/gap_normal.cpp",
         old="    zero_outside_extents_ = false; // the half-space pressure overwrites it below",
         new="    zero_outside_extents_ = true;", tests=GAP,
         require=["test_nonhertz_fastsim"]),
    dict(id="gap-fastsim-spin-origin", what="FASTSIM on a gap takes the spin about the grid's origin",
         file="core/gap/gap_march.cpp",
         old="        r.ox = (in.xi - in.phi * M.yc) / M.L1 - in.phi * (r.y - M.yc) / M.L3;",
         new="        r.ox = in.xi / M.L1 - in.phi * r.y / M.L3;", tests=GAP,
         require=["test_nonhertz_fastsim"]),
    dict(id="gap-fastsim-patch-ellipse", what="the patch ellipse's a is the longest row, not half of it",
         file="core/gap/gap_fastsim_model.cpp",
         old="        const double a = 0.5 * longest_[p], b = elements * grid_.dx * grid_.dy / (kPi * a);",
         new="        const double a = longest_[p], b = elements * grid_.dx * grid_.dy / (kPi * a);",
         tests=GAP, require=["test_nonhertz_fastsim"]),
]
MUTANTS += GAP_MUTANTS
# The exact normal problem's warm solves on a gap grid (core/normal/gap_normal.cpp,
# pressure_drift.cpp, normal_problem.cpp): caught by the drift prediction on linear
# fields and the warm normal solves' products along a drifting gap
# (test_nonhertz_parts), and the exact model's warm drift on a patch (test_nonhertz_model).
WARM_NORMAL = ["test_nonhertz_parts", "test_nonhertz_model"]
MUTANTS += [
    dict(id="normal-drift-off", what="the normal problem's warm start is the last pressure",
         file="core/normal/pressure_drift.cpp",
         old="        start[k] = p0[k] + g[0] * (p1[k] - p0[k]) + g[1] * (p2[k] - p0[k]);",
         new="        start[k] = p0[k];", tests=WARM_NORMAL),
    dict(id="normal-drift-mean", what="the drift's fit keeps the gap's mean with the force prescribed",
         file="core/normal/pressure_drift.cpp",
         old="    if (force) {", new="    if (false) {", tests=WARM_NORMAL),
    dict(id="normal-warm-loose-passes", what="a warm normal solve takes the loose first passes",
         file="core/normal/gap_normal.cpp",
         old="                                       warm ? tolerance : kNormalFirstTolerance,",
         new="                                       kNormalFirstTolerance,", tests=WARM_NORMAL),
    dict(id="normal-share-product-again", what="a pass's first residual takes the share's product again",
         file="core/normal/normal_problem.cpp",
         old="    if (!u_current) set_product(conv, q_, u_, false);",
         new="    set_product(conv, q_, u_, false);", tests=WARM_NORMAL),
    dict(id="normal-start-product-units", what="the start's predicted product is left in the "
         "pressures' units (not divided by G)", file="core/normal/gap_normal.cpp",
         old="            for (double& v : start_product_) v /= in.G;",
         new="            for (double& v : start_product_) v /= 1.0;", tests=WARM_NORMAL),
    dict(id="normal-start-product-newest", what="the start's predicted product is the newest "
         "solution's product whatever the step", file="core/normal/pressure_drift.cpp",
         old="        product[k] = u0[k] + g[0] * (u1[k] - u0[k]) + g[1] * (u2[k] - u0[k]);",
         new="        product[k] = u0[k];", tests=WARM_NORMAL),
]
# The half-space products' pruned transforms (core/halfspace/batched_fft.cpp):
# a zero input taken as nonzero costs only time, a nonzero one dropped or an
# output left unwritten changes every product: the pruned transforms against
# the full ones bit for bit, the products against direct sums, CONTACT's rows.
FFT = ["test_core_exact_parts", "test_core_exact_reference", "test_core_exact_model",
       "test_nonhertz_contact", "test_nonhertz_model"]
MUTANTS += [
    dict(id="fft-prune-inputs", what="a pruned first stage drops the last nonzero input of a "
         "sub-transform", file="core/halfspace/batched_fft.cpp",
         old="        const int K = std::min(R, std::max(0, (nonzero - p0 + m - 1) / m));",
         new="        const int K = std::min(R, std::max(0, (nonzero - p0) / m));",
         tests=FFT, require=["test_core_exact_parts"]),
    dict(id="fft-prune-outputs", what="a pruned last stage stores one output too few",
         file="core/halfspace/batched_fft.cpp",
         old="        const int J = std::min(R, std::max(0, (needed - q0 + s - 1) / s));",
         new="        const int J = std::min(R, std::max(0, (needed - q0) / s));",
         tests=FFT, require=["test_core_exact_parts"]),
    dict(id="fft-even-kernel-mirror", what="an even kernel's mirrored column lands one cell short",
         file="core/halfspace/grid_convolution.cpp",
         old="        const size_t c1 = k == 0 ? 0 : mx_ - k;",
         new="        const size_t c1 = k == 0 ? 0 : mx_ - k - 1;",
         tests=FFT, require=["test_core_exact_parts"]),
    dict(id="fft-copied-spectra", what="the gap model's fine grid copies K33's spectrum for alpha",
         file="core/halfspace/grid_convolution.cpp",
         old="    std::copy(from.alpha_.begin(), from.alpha_.begin() + m, alpha_.begin());",
         new="    std::copy(from.k33_.begin(), from.k33_.begin() + m, alpha_.begin());",
         tests=FFT, require=["test_core_exact_parts", "test_nonhertz_contact"]),
    # The products' SIMD kernels (explicit vectors over the lines, a scalar
    # tail; the spectral product's mirrored reads; the transposes' and the
    # column pairs' edges): each skipped or shifted value changes a product.
    dict(id="fft-vector-tail", what="a stage skips the values after its last full vector",
         file="core/halfspace/batched_fft.cpp",
         old="        for (; t < t1; ++t) butterfly<double, R, Sign, K, J>(",
         new="        for (; t < vector_end; ++t) butterfly<double, R, Sign, K, J>(",
         tests=FFT, require=["test_core_exact_parts"]),
    dict(id="fft-mirror-first-vector", what="the spectral product's first vector mirrors one "
         "row too far", file="core/halfspace/grid_convolution.cpp",
         old="                    m0r[l] = mr[my - l];", new="                    m0r[l] = mr[my - l - 1];",
         tests=FFT, require=["test_core_exact_parts"]),
    dict(id="fft-mirror-not-reversed", what="the spectral product reads z^(-k) forwards",
         file="core/halfspace/grid_convolution.cpp",
         old="                         reversed<W>(simd::load<W>(mi + back)), fr, fi,",
         new="                         simd::load<W>(mi + back), fr, fi,",
         tests=FFT, require=["test_core_exact_parts"]),
    dict(id="fft-transpose-edge", what="a transpose drops the columns after its last block",
         file="core/halfspace/grid_convolution.cpp",
         old="            for (int c = cb; c < cols; ++c)", new="            for (int c = cb; c < cb; ++c)",
         tests=FFT, require=["test_core_exact_parts"]),
    dict(id="fft-pair-split", what="the column pairs' split (AVX2) takes the second column of "
         "each pair as the first", file="core/halfspace/grid_convolution.cpp",
         old="                        simd::store<4>(a + c, __builtin_shufflevector(x, y, 0, 2, 4, 6));",
         new="                        simd::store<4>(a + c, __builtin_shufflevector(x, y, 1, 3, 5, 7));",
         tests=FFT, require=["test_core_exact_parts"]),
    dict(id="fft-real-spectrum-tail", what="the normal product leaves its last spectrum line "
         "unscaled", file="core/halfspace/grid_convolution.cpp",
         old="            for (; ky < lines; ++ky) {", new="            for (; ky + 1 < lines; ++ky) {",
         tests=FFT, require=["test_core_exact_parts"]),
    # The normal problem's conjugate gradients start from the pass's product
    # only with the force prescribed; with the approach prescribed u_ is stale.
    dict(id="normal-stale-first-product", what="the normal problem's gradients reuse a stale "
         "product with the approach prescribed", file="core/normal/normal_problem.cpp",
         old="        const bool u_current = fixed_sum || start_product;",
         new="        const bool u_current = true;",
         tests=GAP + ["test_nonhertz_jacobian", "test_wheelrail_forces"]),
]
# The solved-contact view's one export (core/contact/solved_contact.*,
# solved_strips.cpp): every model's fields read through it.
VIEW = EXACT + GAP + ["test_core_symmetry", "test_capi_solver"]
MUTANTS += [
    dict(id="view-mirror", what="the view ignores the rolling direction's mirror",
         file="core/contact/solved_contact.cpp",
         old="for (int i = 0; i < nx; ++i) op(row + i, value(k0 + (mirrored ? nx - 1 - i : i), i, j));",
         new="for (int i = 0; i < nx; ++i) op(row + i, value(k0 + i, i, j));",
         tests=VIEW, require=["test_core_exact_model", "test_nonhertz_model"]),
    dict(id="view-slip-mask", what="the exact models' slip field outside the slip elements",
         file="core/contact/solved_contact.cpp",
         old="                return state[k] == 2 ? d * S * s[k].real() : 0.0;",
         new="                return d * S * s[k].real();",
         tests=VIEW, require=["test_core_exact_model", "test_nonhertz_model"]),
    dict(id="view-strips-mirror", what="the march models' view ignores the rolling direction",
         file="core/march/march_model.cpp",
         old="    c.mirrored = setup_.direction > 0; // the march starts at the leading edge",
         new="    c.mirrored = false; // the march starts at the leading edge",
         tests=CORE + WEAR + CALIBRATED + ["test_core_march_segments", "test_capi_surface"]),
    dict(id="view-kept-stale", what="the solver keeps the view of an earlier solve",
         file="core/solver.cpp",
         old="    view_made_ = false; // the next read makes the view of this solve",
         new="    // the next read makes the view of this solve",
         tests=CORE + GAP + COLD + ["test_capi_accumulator", "test_capi_wear",
                                    "test_robustness_noalloc_core", "test_capi_vs_core"]),
]
# The Jacobians on a gap grid (core/gap/gap_exact_jacobian.cpp,
# core/gap/gap_fastsim_jacobian.cpp and their parts): caught by central
# differences of the solves and the elliptic exact model's Jacobian
# (test_nonhertz_jacobian), and the C and Fortran doors' own differences.
GAP_JACOBIAN = [
    "test_nonhertz_jacobian", "test_capi_jacobian", "test_fortran_gap",
    "cli_gap_jacobian_matches_library", "python_test_gap_cli",
]
GAP_JACOBIAN_MUTANTS = [
    dict(id="gap-jac-bound-homogeneity", what="the local derivative by the bound drops -J c",
         file="core/exact/steady_rolling.cpp",
         old="                d += (gq_[k] - jc) * (dg[k] / g_[k]);",
         new="                d += gq_[k] * (dg[k] / g_[k]);",
         tests=GAP_JACOBIAN, require=["test_nonhertz_jacobian"]),
    dict(id="gap-jac-normal-cg-step", what="the normal problem's derivative takes unit CG steps",
         file="core/normal/normal_problem.cpp",
         old="            z[k] += step * p_[k];",
         new="            z[k] += p_[k];",
         tests=GAP_JACOBIAN, require=["test_nonhertz_jacobian"]),
    dict(id="gap-jac-bound-scale", what="the bound's change divided by mu p_max, not p_max",
         file="core/gap/gap_exact_jacobian.cpp",
         old="                dp_dN_[box_i0_ + i + static_cast<size_t>(nx_) * (box_j0_ + j)] / s.p_ref;",
         new="                dp_dN_[box_i0_ + i + static_cast<size_t>(nx_) * (box_j0_ + j)] / s.traction_scale;",
         tests=GAP_JACOBIAN, require=["test_nonhertz_jacobian"]),
    dict(id="gap-jac-spin-column", what="the spin's rigid slip takes +y along x in the exact "
         "models' Jacobians", file="core/exact/tangential_solve.hpp",
         old="                                                          : Complex(-yj, x(i) + offset);",
         new="                                                          : Complex(yj, x(i) + offset);",
         tests=GAP_JACOBIAN, require=["test_nonhertz_jacobian"]),
    dict(id="semi-hertz-derivative", what="the semi-Hertzian dp/dd grows with p instead of 1/p",
         file="core/normal/semi_hertz_derivative.cpp",
         old="            dp_dN[k] = p > 0.0 ? 0.5 * P2 / p : 0.0;",
         new="            dp_dN[k] = p > 0.0 ? 0.5 * P2 * p : 0.0;",
         tests=GAP_JACOBIAN, require=["test_nonhertz_jacobian"]),
    dict(id="gap-march-tangent-projection", what="FASTSIM's slip derivative skips the projection",
         file="core/contact/friction_law.hpp",
         old="    dqx = s.f * (dqx - ex * along);",
         new="    dqx = s.f * dqx;",
         tests=GAP_JACOBIAN + ["test_core_friction_law"],
         require=["test_nonhertz_jacobian", "test_core_friction_law"]),
    dict(id="gap-march-tangent-bound", what="FASTSIM's N column misses the bound's own change",
         file="core/gap/gap_march_tangent.cpp",
         old="                dqx[3] += ex * dbound;",
         new="                dqx[3] += 0.0 * dbound;",
         tests=GAP_JACOBIAN, require=["test_nonhertz_jacobian"]),
    dict(id="gap-fastsim-jac-frame", what="FASTSIM's gap Jacobian ignores the rolling direction for xi_x",
         file="core/gap/gap_fastsim_jacobian.cpp",
         old="    const double frame[3] = {d, 1.0, d}, dc[4] = {d, 1.0, d, 1.0};",
         new="    const double frame[3] = {d, 1.0, d}, dc[4] = {1.0, 1.0, d, 1.0};",
         tests=GAP_JACOBIAN, require=["test_nonhertz_jacobian"]),
]
MUTANTS += GAP_JACOBIAN_MUTANTS
# FASTSIM on a gap grid under a law of the slip speed (gap/gap_march.hpp,
# gap_march.cpp, gap_march_tangent.cpp): caught by the ellipse's law march
# on the same pressure, the closed form of full sliding and central
# differences (test_nonhertz_fastsim_law), the C ABI's closed form and
# differences (test_nonhertz_capi) and the fast wheel/rail model in full
# sliding (test_wheelrail_friction).
GAP_LAW = ["test_nonhertz_fastsim_law", "test_nonhertz_capi", "test_wheelrail_friction"]
GAP_LAW_MUTANTS = [
    dict(id="gap-law-slip-speed-step", what="the gap march's slip speed forgets the step dx",
         file="core/gap/gap_march.hpp",
         old="    e.c = in.V * e.Lq / (e.P * in.dx);",
         new="    e.c = in.V * e.Lq / e.P;",
         tests=GAP_LAW, require=["test_nonhertz_fastsim_law", "test_nonhertz_capi"]),
    dict(id="gap-law-slip-onset", what="an element slips past mu_kin pz, not the law's mu(0) pz",
         file="core/gap/gap_march.hpp",
         old="    const double bound = pz * static_friction(*in.speed_law), n2 = qx * qx + qy * qy;",
         new="    const double bound = pz * in.law.mu, n2 = qx * qx + qy * qy;",
         tests=GAP_LAW, require=["test_nonhertz_fastsim_law"]),
    dict(id="gap-law-direction", what="a slipping element under a law keeps q_y unscaled",
         file="core/gap/gap_march.cpp",
         old="            qy *= e.f;",
         new="            qy *= 1.0;",
         tests=GAP_LAW, require=["test_nonhertz_fastsim_law"]),
    dict(id="gap-law-tangent-dc", what="the law's Jacobian holds the slip-speed factor c fixed",
         file="core/gap/gap_march_tangent.cpp",
         old="        const double dc = c * (dLq / e.Lq - dP / P);",
         new="        const double dc = 0.0 * (dLq / e.Lq - dP / P);",
         tests=GAP_LAW, require=["test_nonhertz_fastsim_law", "test_nonhertz_capi"]),
    dict(id="gap-law-tangent-pressure", what="the law's N column misses the bound's own change",
         file="core/gap/gap_march_tangent.cpp",
         old="        if (k == 3) dt += e.r.mu * dpz;",
         new="        if (k == 3) dt += 0.0 * dpz;",
         tests=GAP_LAW, require=["test_nonhertz_fastsim_law", "test_nonhertz_capi"]),
]
MUTANTS += GAP_LAW_MUTANTS
# -------------------------------------------------- end contacts of any shape


# ---------------------------------------------------------- transient rolling
# core/transient over the steady solver's shift operator: caught by CONTACT's
# transient examples through the core and through the C ABI.
TRANSIENT = ["test_transient_contact", "test_capi_transient"]
TRANSIENT_MUTANTS = [
    dict(id="transient-no-transport", what="a step forgets the transport of the state before (d B q0)",
         file="core/transient/transient_contact.cpp",
         old="    for (int k = 0; k < bn_; ++k) base_[k] = d * bq0_[k] - aq0_[k];",
         new="    for (int k = 0; k < bn_; ++k) base_[k] = -aq0_[k];",
         tests=TRANSIENT, require=["test_transient_contact"]),
    dict(id="transient-restore-stale", what="restore keeps the handle's tractions, not the saved ones",
         file="core/transient/transient_contact.cpp",
         old="    q0_ = q;",
         new="    (void)q;",
         tests=TRANSIENT, require=["test_transient_contact"]),
    dict(id="transient-work-scale", what="the slip's dissipation misses the slip's unit",
         file="core/transient/transient_contact.cpp",
         old="    r.W_slip = T_ * U_ * area * w;",
         new="    r.W_slip = T_ * area * w;",
         tests=TRANSIENT, require=["test_transient_contact"]),
    dict(id="transient-work-energy", what="the step's work forgets the change of elastic energy",
         file="core/transient/transient_contact.cpp",
         old="    r.W_step = T_ * U_ * area * (rigid - energy);",
         new="    r.W_step = T_ * U_ * area * rigid;",
         tests=TRANSIENT, require=TRANSIENT),
    dict(id="transient-jacobian-pivot", what="a prescribed force's derivative not inverted",
         file="core/transient/transient_contact.cpp",
         old="        J[p][p] = 1.0 / a;",
         new="        J[p][p] = a;",
         tests=TRANSIENT, require=TRANSIENT),
    dict(id="transient-world-transport", what="world-fixed steps transport the state as contact-fixed ones",
         file="core/transient/transient_contact.cpp",
         old="    const double d = world_ ? 0.0 : std::min(s.dq / dx_, 1.0);",
         new="    const double d = std::min(s.dq / dx_, 1.0);",
         tests=TRANSIENT + ["cli_transient_world_coordinates"], require=TRANSIENT),
    dict(id="transient-ellipse-origin", what="the ellipse's grid starts at the box's edge, not the element centre",
         file="core/transient/ellipse_gap.cpp",
         old="    e.grid.x0 = -S * in.a + 0.5 * e.grid.dx;",
         new="    e.grid.x0 = -S * in.a;",
         tests=TRANSIENT, require=TRANSIENT),
    dict(id="transient-wear-per-distance", what="a step's work fed to the wear law not per rolled distance",
         file="core/wear/transient_wear.cpp",
         old="        work_[k] /= dq;",
         new="        (void)work_[k];",
         tests=TRANSIENT, require=TRANSIENT),
]
MUTANTS += TRANSIENT_MUTANTS

# FASTSIM's transient form (core/transient/transient_fastsim.cpp): caught by
# the steady FASTSIM and the exact history through the core, and the closed
# forms and the steady FASTSIM through the C ABI.
TRANSIENT_FASTSIM = ["test_transient_fastsim", "test_capi_transient"]
TRANSIENT_FASTSIM_MUTANTS = [
    dict(id="transient-fastsim-transport", what="a FASTSIM step reads the state upstream the wrong way",
         file="core/transient/transient_fastsim.cpp",
         old="                src = (1.0 - d) * p0_[k] + d * (last ? zero : p0_[k + 1]);",
         new="                src = d * p0_[k] + (1.0 - d) * (last ? zero : p0_[k + 1]);",
         tests=TRANSIENT_FASTSIM, require=TRANSIENT_FASTSIM),
    dict(id="transient-fastsim-shift-flexibility", what="a shift takes Kalker's rolling L1, not Ls",
         file="core/transient/transient_fastsim.cpp",
         old="            const double L1 = rolling ? P.L1 : P.Ls, L2 = rolling ? P.L2 : P.Ls;",
         new="            const double L1 = P.L1, L2 = P.L2;",
         tests=TRANSIENT_FASTSIM, require=TRANSIENT_FASTSIM),
    dict(id="transient-fastsim-work-area", what="FASTSIM's work field misses the element's area",
         file="core/transient/transient_fastsim.cpp",
         old="        out[k] = state_[k] == 2 ? -area * (p_[k].real() * slip_[k].real() +",
         new="        out[k] = state_[k] == 2 ? -(p_[k].real() * slip_[k].real() +",
         tests=["test_capi_transient", "python_test_transient"],
         require=["test_capi_transient", "python_test_transient"]),
    dict(id="transient-fastsim-world-accepted", what="FASTSIM takes world-fixed coordinates it cannot run",
         file="core/transient/transient_model.cpp",
         old="    if (frame == TransientFrame::world)",
         new="    if (false && frame == TransientFrame::world)",
         tests=["test_capi_transient", "python_test_transient", "test_fortran_transient",
                "octave_test_transient", "cli_transient_bad_inputs_fail_cleanly"],
         require=["test_capi_transient", "python_test_transient"]),
]
MUTANTS += TRANSIENT_FASTSIM_MUTANTS
# ------------------------------------------------------ end transient rolling


# ---------------------------------------------------------------- wheel/rail
# The chain from a patch's geometry to its forces (core/wheelrail/
# patch_contact.cpp): CONTACT's module-1 signs and the rigid slip about the
# reference point, caught by CONTACT's Manchester results and the doors.
WHEELRAIL = [
    "test_wheelrail_forces", "test_wheelrail_capi", "test_fortran_wheelrail",
    "cli_wheelrail_json_matches_library", "test_wheelrail_vertical",
]
WHEELRAIL_MUTANTS = [
    dict(id="wheelrail-cksi-sign", what="CONTACT's CKSI taken as the wheel's xi_x without the sign",
         file="core/wheelrail/patch_contact.cpp",
         old="    const double xi = -p.cksi, eta = p.ceta, phi = p.cphi;",
         new="    const double xi = p.cksi, eta = p.ceta, phi = p.cphi;",
         tests=WHEELRAIL, require=["test_wheelrail_forces"]),
    dict(id="wheelrail-moment-transfer", what="a patch's Mn about the grid's origin, not the reference point",
         file="core/wheelrail/patch_contact.cpp",
         old="    r.mn = t.Mz + x0 * t.Fy - y0 * t.Fx; // about the reference point",
         new="    r.mn = t.Mz; // about the reference point",
         tests=WHEELRAIL),
]
# A solved patch's fields, solver view and wear on the profiles
# (capi/capi_wheelrail_patch.cpp, core/wheelrail/wheelrail_geometry.cpp),
# and the fast model's settings (core/wheelrail/patch_contact.cpp).
WHEELRAIL_PATCH = [
    "test_wheelrail_patch_capi", "test_fortran_wheelrail", "python_test_wheelrail",
    "example_rail_wear_hunting_exact", "example_rail_wear_hunting_fast", "test_wheelrail_forces",
]
WHEELRAIL_MUTANTS += [
    dict(id="wheelrail-field-traction-sign", what="the rail's traction along x given with the wheel's sign",
         file="capi/capi_wheelrail_patch.cpp",
         old="    case CW_FIELD_SX: sign = -1.0; break;",
         new="    case CW_FIELD_SX: break;",
         tests=WHEELRAIL_PATCH),
    dict(id="wheelrail-wear-strip-offset", what="the strips placed from the grid's first row, not the reference point",
         file="capi/capi_wheelrail_patch.cpp",
         old="            for (double& s : ps.s) s = -(s + p.y0); // the solver's y to the patch's s",
         new="            for (double& s : ps.s) s = -s; // the solver's y to the patch's s",
         tests=WHEELRAIL_PATCH),
    dict(id="wheelrail-rail-axis-side", what="the rail's d y / d s without the left side's reversed s",
         file="core/wheelrail/wheelrail_geometry.cpp",
         old="        cp.rail_s_cos = sgn * ref.r.col(1).dot(rail_frame_.r.col(1));",
         new="        cp.rail_s_cos = ref.r.col(1).dot(rail_frame_.r.col(1));",
         tests=WHEELRAIL_PATCH),
    dict(id="wheelrail-fast-model", what="the model setting ignored (always the exact model)",
         file="core/wheelrail/patch_contact.cpp",
         old="    in.model = settings_.model;",
         new="    in.model = ModelKind::exact;",
         tests=WHEELRAIL_PATCH),
]
# The force balance on the wheelset height (core/wheelrail/vertical_force.cpp,
# patch_contact.cpp) and the normal methods' derivative by the approach it
# steps with: evaluations per call, pinned on a sphere-like contact and on a
# drifting host through the class and the C ABI.
BALANCE = [
    "test_wheelrail_vertical", "test_wheelrail_forces", "test_wheelrail_capi", "test_nonhertz_parts",
]
WHEELRAIL_MUTANTS += [
    dict(id="wheelrail-newton-slope", what="the force balance without the patches' derivative (regula falsi)",
         file="core/wheelrail/vertical_force.cpp",
         old="        if (e.fz > 0.0 && e.slope > 0.0) p.slope = 2.0 / 3.0 * e.slope / std::cbrt(e.fz);",
         new="        if (e.fz > 0.0 && e.slope > 0.0) p.slope = 0.0;",
         tests=BALANCE, require=["test_wheelrail_vertical", "test_wheelrail_forces"]),
    dict(id="semi-hertz-force-by-depth", what="the semi-Hertzian dN/dd sums P^2 p instead of P^2 / p",
         file="core/normal/semi_hertz_derivative.cpp",
         old="            if (p[i] > 0.0) total += 0.5 * P2 / p[i];",
         new="            if (p[i] > 0.0) total += 0.5 * P2 * p[i];",
         tests=BALANCE, require=["test_nonhertz_parts", "test_wheelrail_forces"]),
    dict(id="wheelrail-drift-extrapolation", what="a drifting host's start not extrapolated",
         file="core/wheelrail/patch_contact.cpp",
         old="start.z = 2.0 * balance_z_[1] - balance_z_[0];",
         new="start.z = balance_z_[1];",
         tests=BALANCE, require=["test_wheelrail_forces"]),
    dict(id="wheelrail-search-height-shift", what="the later heights' search samples not shifted by the height",
         file="core/wheelrail/contact_search.cpp",
         old="                zw_[i] = zw_sampled_[i] + dz;",
         new="                zw_[i] = zw_sampled_[i];",
         tests=["test_wheelrail_geometry"] + BALANCE, require=["test_wheelrail_geometry", "test_wheelrail_forces"]),
    # The later heights' wheel solves from the last height's points
    # (core/wheelrail/patch_grid.cpp): a step's warm start misses by more
    # than their stop only after steps larger than a balance's (within a
    # balance one Newton step reaches rounding whatever the stop), and
    # only the geometry's own callers move it sideways between heights:
    # the geometry test and the vertical test's fixed-grid steps catch them.
    dict(id="wheelrail-warm-wheel-stop", what="the later heights' wheel solves stopped at a step below 1e-3 m",
         file="core/wheelrail/patch_grid.cpp",
         old="constexpr double kWarmStep = 1e-8; ",
         new="constexpr double kWarmStep = 1e-3; ",
         tests=["test_wheelrail_geometry"] + BALANCE, require=["test_wheelrail_geometry", "test_wheelrail_vertical"]),
    dict(id="wheelrail-warm-wheel-moved", what="the last height's wheel points used after a lateral move",
         file="core/wheelrail/patch_grid.cpp",
         old="           kept->wheel.o(0) == wheel.o(0) && kept->wheel.o(1) == wheel.o(1);",
         new="           true;",
         tests=["test_wheelrail_geometry"] + BALANCE, require=["test_wheelrail_geometry", "test_wheelrail_vertical"]),
    # The search's sampling leaves out the wheel knots whose locus cannot
    # reach a rail sample (core/wheelrail/contact_search.cpp).
    dict(id="wheelrail-locus-knots-above", what="the locus' knots cut at the first sample instead of the last",
         file="core/wheelrail/contact_search.cpp",
         old="    while (k_sta < k_end && ky_[k_sta + 1] - reach(k_sta + 1) > y_last) ++k_sta;",
         new="    while (k_sta < k_end && ky_[k_sta + 1] - reach(k_sta + 1) > y0_) ++k_sta;",
         tests=["test_wheelrail_geometry"] + BALANCE, require=["test_wheelrail_geometry", "test_wheelrail_forces"]),
    dict(id="wheelrail-locus-knots-below", what="the locus' knots cut at the last sample instead of the first",
         file="core/wheelrail/contact_search.cpp",
         old="    while (k_end > k_sta && ky_[k_end - 1] + reach(k_end - 1) < y0_) --k_end;",
         new="    while (k_end > k_sta && ky_[k_end - 1] + reach(k_end - 1) < y_last) --k_end;",
         tests=["test_wheelrail_geometry"] + BALANCE, require=["test_wheelrail_geometry", "test_wheelrail_forces"]),
    # The yaw's share of the reach moves the locus only at the rail's far
    # ends, away from any contact: only the samples show it.
    dict(id="wheelrail-locus-reach-yaw", what="the locus' reach without the yaw's share",
         file="core/wheelrail/contact_search.cpp",
         old="        return std::abs(r(1, 0)) * 0.5 * R + std::abs(r(1, 2)) * (R + std::abs(knot_[k].z)) + kReachSlack;",
         new="        return std::abs(r(1, 2)) * (R + std::abs(knot_[k].z)) + kReachSlack;",
         tests=["test_wheelrail_geometry"], require=["test_wheelrail_geometry"], min_caught=1),
    dict(id="wheelrail-balance-last-evaluation", what="the forces returned from every evaluation's patches, not the last's",
         file="core/wheelrail/patch_contact.cpp",
         old="            evaluated_.clear();",
         new="            evaluated_.reserve(8);",
         tests=BALANCE, require=["test_wheelrail_forces", "test_wheelrail_capi"]),
    dict(id="wheelrail-balance-final-solve", what="a trial height's force accepted without the final solve",
         file="core/wheelrail/vertical_force.cpp",
         old="            const Evaluation f = patch_forces(g.state(), final);",
         new="            const Evaluation f = e;",
         tests=BALANCE, require=["test_wheelrail_vertical", "test_wheelrail_forces"]),
    dict(id="wheelrail-balance-final-tolerance", what="the exact balance's final solve to the trials' tolerance",
         file="core/wheelrail/patch_contact.cpp",
         old="        const PatchSolution& s = contact_.solve(p, k);",
         new="        const PatchSolution& s = contact_.solve(p, k, false, kTrialTolerance);",
         tests=BALANCE, require=["test_wheelrail_forces", "test_wheelrail_capi"]),
    # The exact balance's start (the fast model's height) and its trials'
    # looser normal problem, solved again at the height accepted.
    dict(id="wheelrail-exact-start-fast", what="the exact balance from the Hertz estimate's height",
         file="core/wheelrail/patch_contact.cpp",
         old="        return solve_vertical_position(geometry_, fz, start, velocity, fast, options).z;",
         new="        (void)fast; throw Error(ErrorKind::not_converged, \"no fast start\");",
         tests=BALANCE, require=["test_wheelrail_forces", "test_wheelrail_capi"]),
    dict(id="normal-held-tolerance", what="a final solve keeps the trial's normal solution to 1e-6",
         file="core/normal/gap_normal.cpp",
         old="    if (h.method == NormalMethod::exact && h.tolerance > normal_tolerance(in)) return false;",
         new="    if (h.method == NormalMethod::exact && h.tolerance > 1.0) return false;",
         tests=BALANCE, require=["test_wheelrail_forces", "test_wheelrail_capi"]),
    dict(id="wheelrail-law-speed", what="a patch's law takes twice its rolling speed",
         file="core/wheelrail/patch_contact.cpp",
         old="        in.V = p.veloc;",
         new="        in.V = 2.0 * p.veloc;",
         tests=["test_wheelrail_friction", "python_test_wheelrail"],
         require=["test_wheelrail_friction", "python_test_wheelrail"]),
    dict(id="wheelrail-law-term", what="a patch's law without its first falling term",
         file="core/wheelrail/patch_contact.cpp",
         old="        in.mu_e1 = settings_.mu_e1;",
         new="        in.mu_e1 = 0.0;",
         tests=["test_wheelrail_friction", "python_test_wheelrail"],
         require=["test_wheelrail_friction", "python_test_wheelrail"]),
    # Memory and layer in the patches: against cw_solve on the patch's gap,
    # the Python door's keywords; the layer's units by the contact's rules.
    dict(id="wheelrail-layer", what="a patch without its interface layer",
         file="core/wheelrail/patch_contact.cpp",
         old="    in.layer_h = settings_.layer_h;",
         new="    in.layer_h = 0.0;",
         tests=["test_wheelrail_layer", "python_test_wheelrail"],
         require=["test_wheelrail_layer", "python_test_wheelrail"]),
    dict(id="wheelrail-memory", what="a patch's law without its memory",
         file="core/wheelrail/patch_contact.cpp",
         old="        in.memory_distance = settings_.memory_distance;",
         new="        in.memory_distance = 0.0;",
         tests=["test_wheelrail_layer", "python_test_wheelrail"],
         require=["test_wheelrail_layer", "python_test_wheelrail"]),
    dict(id="wheelrail-layer-units", what="the wheel/rail checks blind to the layer's thickness",
         file="core/wheelrail/placement_checks.cpp",
         old="    layer.layer_h = in.layer_h;",
         new="    layer.layer_h = 0.0;",
         tests=["test_wheelrail_layer", "python_test_wheelrail",
                "cli_wheelrail_memory_and_layer_match_library"],
         require=["test_wheelrail_layer", "python_test_wheelrail"]),
]
MUTANTS += WHEELRAIL_MUTANTS
# ------------------------------------------------------------ end wheel/rail

# ------------------------------------------------------- the shared policy
# The library's plausibility checks, default grids and names
# (core/contact/plausibility.cpp, core/wheelrail/placement_checks.cpp,
# capi/capi_check.cpp), as the C ABI, module creepwork and the CLI show them;
# the Python door's own rules (required inputs, the gap's shape).
POLICY = ["test_capi_check", "test_fortran_checks", "cli_gap_unit_mistakes_warn",
          "cli_warns_and_accepts_any_case"]
WHEELRAIL_POLICY = ["test_wheelrail_capi", "test_fortran_checks",
                    "cli_wheelrail_warns_about_misplaced_wheel"]
POLICY_MUTANTS = [
    dict(id="check-gap-heights", what="a gap's heights warned only beyond 100 m, not 10 mm",
         file="core/contact/plausibility.cpp",
         old="     gap_spread, [](const C& c, double v) { return c.gap_grid && v > 1e-2; }},",
         new="     gap_spread, [](const C& c, double v) { return c.gap_grid && v > 1e2; }},",
         tests=POLICY),
    dict(id="check-semi-axis-input", what="the rule on a reads b",
         file="core/contact/plausibility.cpp",
         old='    {CheckRule::semi_axis, "a", "m", kSemiLarge, [](const C& c) { return c.a; },',
         new='    {CheckRule::semi_axis, "a", "m", kSemiLarge, [](const C& c) { return c.b; },',
         tests=POLICY),
    dict(id="check-default-geometry", what="the placeholders reported only when N was changed",
         file="capi/capi_check.cpp",
         old="    c.default_geometry = p.a == d.a && p.b == d.b && p.normal_force == d.normal_force;",
         new="    c.default_geometry = p.a == d.a && p.b == d.b && p.normal_force != d.normal_force;",
         tests=["test_capi_check", "test_fortran_checks", "python_test_policy"]),
    dict(id="check-alias-fast", what="fast read as another model than fastsim",
         file="capi/capi_check.cpp",
         old='                                                             {"fast", "fastsim"}};',
         new='                                                             {"fast", "exact"}};',
         tests=["test_capi_check", "test_fortran_checks", "cli_wheelrail_one_vocabulary"]),
    dict(id="check-shift-limit", what="a lateral shift warned above 50 mm, not the 20 mm it says",
         file="core/wheelrail/placement_checks.cpp",
         old="constexpr double kShiftLimit = 20e-3;",
         new="constexpr double kShiftLimit = 50e-3;",
         tests=WHEELRAIL_POLICY + ["python_test_wheelrail"]),
    dict(id="check-flange-tip", what="a patch on the flange tip only within 0.05 mm of it",
         file="core/wheelrail/placement_checks.cpp",
         old="constexpr double kTipDepth = 3e-3;",
         new="constexpr double kTipDepth = 0.05e-3;",
         tests=WHEELRAIL_POLICY),
    dict(id="check-profile-origin", what="a flange tip up to 95 mm from the flange back passes",
         file="core/wheelrail/placement_checks.cpp",
         old="constexpr double kTipFromBack = 45e-3;",
         new="constexpr double kTipFromBack = 95e-3;",
         tests=WHEELRAIL_POLICY),
    dict(id="profile-y-offset", what="the profile's lateral offset is not applied",
         file="core/wheelrail/profile_io.cpp",
         old="        pts.push_back({(opt.mirror_y ? -r.y : r.y) * unit + opt.y_offset,",
         new="        pts.push_back({(opt.mirror_y ? -r.y : r.y) * unit,",
         tests=WHEELRAIL_POLICY),
    dict(id="cli-typed-name", what="the CLI names an alias option by its documented name",
         file="programs/cli/options.cpp",
         old="        parsed.typed_[spec->name] = name;",
         new="        parsed.typed_[spec->name] = spec->name;",
         tests=["cli_one_vocabulary", "cli_wheelrail_one_vocabulary"]),
    dict(id="python-required-geometry", what="Python solves without N",
         file="python/creepwork/_params.py",
         old='("a", "a"), ("b", "b"), ("N", "normal_force"))',
         new='("a", "a"), ("b", "b"))',
         tests=["python_test_policy", "python_test_errors"]),
    dict(id="python-gap-shape", what="Python accepts a transposed gap",
         file="python/creepwork/_solver.py",
         old="    if len(shape) < 2 or shape == (ny, nx):",
         new="    if len(shape) < 2 or shape in ((ny, nx), (nx, ny)):",
         tests=["python_test_policy", "python_test_gap"]),
]
MUTANTS += POLICY_MUTANTS
# The surface post-processors' rules (core/contact/surface_plausibility.cpp)
# at the C ABI and at every door that prints them.
SURFACE_POLICY = ["test_capi_check", "test_fortran_surface", "python_test_surface",
                  "octave_test_surface", "cli_surface_warns_about_implausible_units"]
MUTANTS += [
    dict(id="check-conductivity", what="a conductivity in W/(mm K) passes (bound 0.01, not 1)",
         file="core/contact/surface_plausibility.cpp",
         old="    CheckRule::conductivity, \"W/(m K)\", 1.0, 1000.0,",
         new="    CheckRule::conductivity, \"W/(m K)\", 0.01, 1000.0,",
         tests=SURFACE_POLICY),
    dict(id="check-conductivity-body", what="the rule on conductivity_2 reads the rail's",
         file="core/contact/surface_plausibility.cpp",
         old="        check_property(kConductivity, conductivity[body], t.conductivity[body], out);",
         new="        check_property(kConductivity, conductivity[body], t.conductivity[0], out);",
         tests=SURFACE_POLICY),
    dict(id="check-heat-capacity", what="a heat capacity down to 10 J/(kg K) passes",
         file="core/contact/surface_plausibility.cpp",
         old="    CheckRule::heat_capacity, \"J/kg/K\", 100.0, 5000.0,",
         new="    CheckRule::heat_capacity, \"J/kg/K\", 10.0, 5000.0,",
         tests=SURFACE_POLICY),
    dict(id="check-density", what="a density up to 250000 kg/m^3 passes",
         file="core/contact/surface_plausibility.cpp",
         old="    CheckRule::density, \"kg/m^3\", 1000.0, 25000.0,",
         new="    CheckRule::density, \"kg/m^3\", 1000.0, 250000.0,",
         tests=SURFACE_POLICY),
    dict(id="check-rolling-speed", what="a rolling speed warned only above 300 m/s",
         file="core/contact/surface_plausibility.cpp",
         old="    if (t.rolling_speed > kSpeedLimit && std::isfinite(t.rolling_speed))",
         new="    if (t.rolling_speed > 2.0 * kSpeedLimit && std::isfinite(t.rolling_speed))",
         tests=SURFACE_POLICY),
    dict(id="check-yield-stress", what="k_yield warned only below 100 Pa",
         file="core/contact/surface_plausibility.cpp",
         old="    if (d.k_yield > 0.0 && d.k_yield < 1e6)",
         new="    if (d.k_yield > 0.0 && d.k_yield < 1e2)",
         tests=SURFACE_POLICY),
    dict(id="check-wlrm-threshold", what="a WLRM threshold warned only below 0.01 N",
         file="core/contact/surface_plausibility.cpp",
         old="        if (w.v > 0.0 && w.v < 1.0)",
         new="        if (w.v > 0.0 && w.v < 0.01)",
         tests=SURFACE_POLICY),
]
# ----------------------------------------------------- end the shared policy

# ----------------------------------------------------- temperature, damage
# The flash temperature (core/thermal) against the analytic moving-source
# solution, the Ertz case and CONTACT's example, and at every door; the
# damage indices (core/damage) against their definitions and hand values.
SURFACE = [
    "test_core_temperature", "test_core_damage", "test_capi_surface", "test_fortran_surface",
    "python_test_surface", "octave_test_surface", "cli_surface_contact_example",
]
MUTANTS += [
    dict(id="thermal-self-term", what="the consistent self-element term is CONTACT's whole element",
         file="core/thermal/flash_temperature.cpp",
         old="        r.self_weight = std::sqrt(0.5);", new="        r.self_weight = std::sqrt(2.0);",
         tests=SURFACE),
    dict(id="thermal-contact-self-term", what="CONTACT's self-element term taken as the consistent one",
         file="core/thermal/flash_temperature.cpp",
         old="        r.self_weight = std::sqrt(2.0);", new="        r.self_weight = std::sqrt(0.5);",
         tests=SURFACE),
    dict(id="thermal-contact-temperature", what="T_c weights each body by the other's effusivity",
         file="core/thermal/flash_temperature.cpp",
         old="        r.Tc = (b1 * p.rail.T0 + b2 * p.wheel.T0) / (b1 + b2);",
         new="        r.Tc = (b2 * p.rail.T0 + b1 * p.wheel.T0) / (b1 + b2);", tests=SURFACE),
    dict(id="thermal-shared-flash", what="the flash part takes body 1's effusivity twice",
         file="core/thermal/flash_temperature.cpp",
         old="    const double shared = 2.0 / ((b1 + b2) * std::sqrt(kPi * p.rolling_speed));",
         new="    const double shared = 2.0 / ((b1 + b1) * std::sqrt(kPi * p.rolling_speed));",
         tests=SURFACE),
    dict(id="thermal-kernel-weight", what="the moving-source weights off by a tenth of an element",
         file="core/thermal/moving_source.cpp",
         old="    return 1.0 / (std::sqrt(k + 0.5) + std::sqrt(k - 0.5));",
         new="    return 1.0 / (std::sqrt(k + 0.6) + std::sqrt(k - 0.5));", tests=SURFACE),
    dict(id="thermal-recursion-gain", what="the recursion's far sources one element late",
         file="core/thermal/moving_source.cpp",
         old="        gain_.push_back(c[m] * std::exp(-s[m] * K));",
         new="        gain_.push_back(c[m] * std::exp(-s[m] * (K + 1)));", tests=SURFACE),
    dict(id="thermal-relaxation", what="the relaxation behind the contact without its root",
         file="core/thermal/flash_temperature.cpp",
         old="                const double g = 2.0 / kPi * std::asin(std::sqrt(ratio));",
         new="                const double g = 2.0 / kPi * std::asin(ratio);", tests=SURFACE),
    dict(id="thermal-heat-speed", what="the heat from the work map without the rolling speed",
         file="core/thermal/heat_source.cpp",
         old="        simd::store<2>(q + e, rolling_speed * quotient_if_positive(zero < w ? w : zero,",
         new="        simd::store<2>(q + e, 1.0 * quotient_if_positive(zero < w ? w : zero,", tests=SURFACE),
    dict(id="thermal-row-length", what="a strip's element length scaled by b instead of a",
         file="capi/capi_surface.cpp",
         old="                                                        : s.grid().x_length()[j] * c.totals.a;",
         new="                                                        : s.grid().x_length()[j] * c.totals.b;",
         tests=SURFACE),
    dict(id="damage-rcf-floor", what="the RCF index's floor at -0.4",
         file="core/damage/damage_indices.hpp",
         old="constexpr double kRcfNoRisk = -0.5; // CONTACT's floor and exterior value",
         new="constexpr double kRcfNoRisk = -0.4; // CONTACT's floor and exterior value",
         tests=SURFACE),
    dict(id="damage-fi-surf", what="FI_surf with k/p0 taken as 2 A k/(2 F_z)",
         file="core/damage/damage_indices.cpp",
         old="        t.FI_surf = t.mu_eff - 2.0 * in.contact_area * p.k_yield / (3.0 * in.normal_force);",
         new="        t.FI_surf = t.mu_eff - 2.0 * in.contact_area * p.k_yield / (2.0 * in.normal_force);",
         tests=SURFACE),
    dict(id="damage-wlrm-rise", what="WLRM damage rising over onset..zero instead of onset..peak",
         file="core/damage/wlrm.cpp",
         old="    if (T_gamma <= f.peak) return f.peak_damage * (T_gamma - f.onset) / (f.peak - f.onset);",
         new="    if (T_gamma <= f.peak) return f.peak_damage * (T_gamma - f.onset) / (f.zero - f.onset);",
         tests=SURFACE),
]
# Friction that depends on the temperature: the loop against CONTACT's
# euro_tractcurv and the fixed point, at the C ABI, the CLI and Fortran.
MU_T = ["test_capi_mu_temperature", "test_fortran_surface", "cli_surface_mu_T_matches_library"]
MUTANTS += [
    dict(id="mu-t-factor-unit", what="the element's factor is mu(T), not mu(T) over the law's unit",
         file="core/thermal/friction_temperature.cpp",
         old="    for (long e = 0; e < n; ++e) factor[e] = mu_of_temperature(t, T[e]) / mu_ref;",
         new="    for (long e = 0; e < n; ++e) factor[e] = mu_of_temperature(t, T[e]);", tests=MU_T),
    dict(id="mu-t-bound-unscaled", what="the exact model ignores the element-wise factors",
         file="core/exact/exact_model.cpp",
         old="    scale_bounds(ElementFriction{factor_, nx_, setup_.direction < 0}, g.data(), nx_, ny_);",
         new="", tests=MU_T),
    dict(id="mu-t-last-forces", what="the loop keeps Fx as the last pass's Fy",
         file="capi/capi_surface.cpp",
         old="            fy = totals.Fy;", new="            fy = totals.Fx;", tests=MU_T),
]
# mu(T) in FASTSIM and in the exact model on a gap grid: the element-wise
# factors against each element's bound, the fixed point's identity and the
# CLI's runs.
MU_T_MODELS = ["test_core_friction_factors", "test_capi_mu_temperature",
               "cli_surface_mu_T_fastsim", "cli_surface_mu_T_on_a_gap_grid"]
MUTANTS += [
    dict(id="mu-t-march-unscaled", what="FASTSIM's march ignores the element-wise factors",
         file="core/march/march_model.cpp",
         old="        bound_ = factored_.data();", new="", tests=MU_T_MODELS),
    dict(id="mu-t-march-mirror", what="FASTSIM reads the factors with x the wrong way round",
         file="core/march/march_model.cpp",
         old="        const ElementFriction f{factor_, geometry_.nx, setup_.direction > 0};",
         new="        const ElementFriction f{factor_, geometry_.nx, setup_.direction < 0};",
         tests=MU_T_MODELS),
    dict(id="mu-t-gap-unscaled", what="the gap exact model ignores the element-wise factors",
         file="core/gap/gap_exact_model.cpp",
         old="    scale_bounds(box_friction(), g.data(), fine.nx, fine.ny);", new="",
         tests=MU_T_MODELS),
    dict(id="mu-t-gap-box", what="the gap exact model reads the factors from the grid's corner, "
         "not the box's", file="core/gap/gap_exact_model.hpp",
         old="        return ElementFriction{factor_, nx_, setup_.direction < 0, box_i0_, box_j0_};",
         new="        return ElementFriction{factor_, nx_, setup_.direction < 0, 0, box_j0_};",
         tests=MU_T_MODELS),
    dict(id="mu-t-gap-fastsim-unscaled", what="FASTSIM on a gap grid ignores the element-wise "
         "factors", file="core/gap/gap_fastsim_model.cpp",
         old="    m.bound_pressure = factored(m.pressure, bound_p_);", new="", tests=MU_T_MODELS),
    dict(id="mu-t-gap-fastsim-mirror", what="FASTSIM on a gap grid reads the factors with x the "
         "wrong way round", file="core/gap/gap_fastsim_model.cpp",
         old="    const ElementFriction f{factor_, nx_, direction_ < 0};",
         new="    const ElementFriction f{factor_, nx_, direction_ > 0};", tests=MU_T_MODELS),
]
# ------------------------------------------------- end temperature, damage

# ---------------------------------------------------------------- progress
# The progress line of long work (programs/cli/progress.cpp), which the
# campaign prints through the same code as wear and sweep: caught by the
# CLI's progress tests and the campaign's.
PROGRESS = [
    "cli_wear_reports_progress", "cli_sweep_reports_progress", "cli_the_line",
    "campaign_progress_lines",
]
MUTANTS += [
    dict(id="progress-only-at-end", what="progress printed only once the work is done",
         file="programs/cli/progress.cpp",
         old="    if (seconds < next_) return;",
         new="    if (seconds < next_ || done < total_) return;", tests=PROGRESS),
    dict(id="progress-line-words", what="the progress line loses its 'done'",
         file="programs/cli/progress.cpp",
         old='"%s: %llu of %llu %s done (%.0f %%), %.0f %s/s, about %.0f s to go",',
         new='"%s: %llu of %llu %s (%.0f %%), %.0f %s/s, about %.0f s to go",', tests=PROGRESS),
]
# ------------------------------------------------------------ end progress


# ------------------------------------------------------------ promises pinned
# What the newest code promises at the door where a user meets it (issue 40):
# the semi-Hertzian fit's rule, the rail offset with the gauge measured, the
# wear of several wheel/rail patches, the patch array's stride, the Python
# package's pointer fields and unit checks, the MEX gateway's enumeration
# names, the batch's refusal of a smaller result element, the Fortran
# module's strip order. Each is caught by a hand-computed value, a mirrored
# or translated solution, or another door's bits.
PROMISE_MUTANTS = [
    dict(id="semi-hertz-fit-lower-decides", what="the semi-Hertzian fit widens while the lower "
         "element of the next pair penetrates enough, not both",
         file="core/normal/semi_hertz.cpp",
         old="? std::max(row[R.locus - k - 1], row[R.locus + k + 1]) - h_min_",
         new="? std::min(row[R.locus - k - 1], row[R.locus + k + 1]) - h_min_",
         tests=GAP + ["test_nonhertz_parts"]),
    dict(id="wheelrail-gauge-offset-unmirrored", what="with the gauge measured, rail_dy moves the "
         "left rail in its mirrored frame as given (not in track coordinates)",
         file="core/wheelrail/placement.cpp",
         old="f.o = Vec3(0.0, 0.5 * track.gauge_width - y_gauge + sgn * track.rail_dy, -z_top + track.rail_dz);",
         new="f.o = Vec3(0.0, 0.5 * track.gauge_width - y_gauge + track.rail_dy, -z_top + track.rail_dz);",
         tests=WHEELRAIL + ["test_wheelrail_geometry", "test_wheelrail_patch_capi",
                            "test_wheelrail_contact", "python_test_wheelrail"]),
    dict(id="wheelrail-wear-max-depth-sum", what="add_wear's max_depth the patches' sum, not the "
         "deepest's", file="capi/capi_wheelrail_patch.cpp",
         old="            sum.max_depth = std::fmax(sum.max_depth, r.max_depth);",
         new="            sum.max_depth += r.max_depth;", tests=WHEELRAIL_PATCH),
    dict(id="patches-own-stride", what="cw_solver_get_patches writes patch k at k sizeof(cw_patch), "
         "not k out[0].struct_size", file="capi/capi_patches.cpp",
         old="            write_struct(reinterpret_cast<cw_patch*>(bytes + k * size), c);",
         new="            write_struct(&out[k], c);",
         tests=ABI + ["test_nonhertz_capi", "test_fortran_gap", "python_test_gap",
                      "octave_test_gap"]),
    dict(id="python-pointer-memory-order", what="Python passes a pointer field's array in its own "
         "memory order", file="python/creepwork/_params.py",
         old='arr = np.ascontiguousarray(value, dtype=_NUMPY[spec["ctype"]])',
         new='arr = np.asarray(value, dtype=_NUMPY[spec["ctype"]])',
         tests=["python_test_gap", "python_test_many", "python_test_gap_cli",
                "python_test_solver"]),
    dict(id="python-units-keywords-only", what="solve_many and Batch check the keywords' units, "
         "not a params array's", file="python/creepwork/_batch.py",
         old="            _errors.warn_units(_checks.warnings_for(self._grid, recs, typed), stacklevel)",
         new="            _errors.warn_units(_checks.warnings_for(self._grid, recs if params_in is None "
             "else recs[:0], typed), stacklevel)",
         tests=["python_test_units", "python_test_many", "python_test_solver"]),
    dict(id="mex-text-one-contact-per-character", what="the MEX gateway counts an enumeration's "
         "name as one contact per character", file="matlab/creepwork_mex.c",
         old="        if (!v || mxIsChar(v)) continue;", new="        if (!v) continue;",
         tests=["octave_test_many", "octave_test_cli", "octave_test_solver",
                "octave_test_units"]),
    dict(id="batch-smaller-result-element", what="a batch accepts a result element smaller than "
         "results[0]", file="capi/capi_batch.cpp",
         old="            if (p->struct_size != pstride || r->struct_size != rstride)",
         new="            if (p->struct_size != pstride || r->struct_size > rstride)", tests=ABI),
    dict(id="f-wear-strips-order", what="the module's get_strips swaps width and depth",
         file="fortran/creepwork_wear.f90", old="py, pw, pd, pp, n))", new="py, pd, pw, pp, n))",
         tests=FORTRAN),
]
MUTANTS += PROMISE_MUTANTS
# -------------------------------------------------------- end promises pinned

# ------------------------------------------------------------------ friction
# Laws of the slip speed (core/friction) and FASTSIM with a law: CONTACT's
# formulas and its tractcurv rows, closed forms, central differences.
FRICTION = [
    "test_core_slip_speed_laws", "test_core_friction_tractcurv", "test_core_friction_fastsim",
]
MUTANTS += [
    dict(id="law-exp-half-speed", what="exponential law's term halved at s_h/ln 2, not s_h",
         file="core/friction/slip_speed_law.cpp",
         old="        const double e = mu_e * std::exp(-kLn2 * r);",
         new="        const double e = mu_e * std::exp(-r);", tests=FRICTION),
    dict(id="law-exp-slope", what="exponential law's slope without ln 2",
         file="core/friction/slip_speed_law.cpp",
         old="        return {e, -kLn2 * e / s_h};", new="        return {e, -e / s_h};", tests=FRICTION),
    dict(id="law-linear-kink", what="linear law falls to 0 at s_h, not 2 s_h",
         file="core/friction/slip_speed_law.cpp",
         old="        const double f = 1.0 - 0.5 * r;", new="        const double f = 1.0 - r;",
         tests=FRICTION),
    dict(id="law-rational-square", what="rational law's second term not squared",
         file="core/friction/slip_speed_law.cpp",
         old="        const double d = 1.0 + r * r; // mu_e / (1 + (s/s_h)^2)",
         new="        const double d = 1.0 + r; // mu_e / (1 + (s/s_h)^2)", tests=FRICTION),
    dict(id="polach-half-speed", what="Polach's B taken as 1/s_h, without ln 2",
         file="core/friction/slip_speed_law.cpp",
         old="    law.s_h1 = kLn2 / B;", new="    law.s_h1 = 1.0 / B;", tests=FRICTION),
    dict(id="law-march-dt-dc", what="the slipping element's dt/dc with the wrong sign",
         file="core/fastsim/march_law.cpp",
         old="const V dt_dP = gdm * c[g], dt_dc = gdm * (P[g] - t[g]);",
         new="const V dt_dP = gdm * c[g], dt_dc = -(gdm * (P[g] - t[g]));",
         tests=FRICTION + ["test_capi_friction"]),
    dict(id="law-march-ln-t", what="the slip-speed factor c held fixed when T (so N) moves",
         file="core/fastsim/march_law.cpp",
         old="                            if (k == K - 1) dc += c[g];",
         new="                            if (k == K) dc += c[g];",
         tests=FRICTION + ["test_capi_friction"]),
    dict(id="law-march-slip-speed", what="slip speed of a FASTSIM element without the 1/a of its step",
         file="core/fastsim/fastsim_law_model.cpp",
         old="    A.slip_speed_scale = V_ * s.traction_scale / s.a;",
         new="    A.slip_speed_scale = V_ * s.traction_scale;",
         tests=FRICTION + ["test_capi_friction"]),
    dict(id="law-lanes-rational-square", what="the kernels' rational law: second term not squared",
         file="core/friction/slip_speed_law_lanes.hpp",
         old="            const V r = s * rate, d = one + r * r;",
         new="            const V r = s * rate, d = one + r;", tests=FRICTION),
    dict(id="law-march-halley", what="the law march's Halley step without its curvature (Newton's)",
         file="core/fastsim/march_law.cpp",
         old="        const V den0 = two_slope2 - k.res * curv;",
         new="        const V den0 = two_slope2;", tests=FRICTION),
    dict(id="law-march-stop", what="the law march's last Halley step up to 1e-2 g, not 1e-4 g",
         file="core/fastsim/march_law.cpp",
         old="constexpr double kLawStepTolerance = Kind == SlipSpeedLawKind::linear ? 1e-8 : 1e-4;",
         new="constexpr double kLawStepTolerance = Kind == SlipSpeedLawKind::linear ? 1e-8 : 1e-2;",
         tests=FRICTION),
    dict(id="law-lanes-exp-curvature", what="the kernels' exponential law: curvature of the wrong sign",
         file="core/friction/slip_speed_law_lanes.hpp",
         old="            if constexpr (Curvature) d2m = -(rate * dm);",
         new="            if constexpr (Curvature) d2m = rate * dm;", tests=FRICTION),
    dict(id="law-lanes-rational-curvature", what="the kernels' rational law: second term's curvature 6 r^2 + 2",
         file="core/friction/slip_speed_law_lanes.hpp",
         old="                d2m = e * rate * rate * (simd::broadcast<W>(6.0) * r * r - simd::broadcast<W>(2.0)) /",
         new="                d2m = e * rate * rate * (simd::broadcast<W>(6.0) * r * r + simd::broadcast<W>(2.0)) /",
         tests=FRICTION),
    dict(id="simd-exp-cubic", what="the kernels' exp with 1/5 for the cubic Taylor coefficient",
         file="core/simd/simd_exp.hpp",
         old="p23 = broadcast<W>(0.5) + broadcast<W>(1.0 / 6.0) * r,",
         new="p23 = broadcast<W>(0.5) + broadcast<W>(1.0 / 5.0) * r,", tests=FRICTION),
    dict(id="spiryagin-alpha", what="Spiryagin's alpha_inf and 1 - alpha_inf swapped",
         file="core/friction/global_slip.cpp",
         old="    g.k = sr.k0 * (sr.alpha_inf + (1.0 - sr.alpha_inf) / (1.0 + sr.beta * g.epsilon));",
         new="    g.k = sr.k0 * ((1.0 - sr.alpha_inf) + sr.alpha_inf / (1.0 + sr.beta * g.epsilon));",
         tests=FRICTION),
]
# The exact models under a law of the slip speed (core/exact/local_friction,
# exact_law, steady_rolling's sources): CONTACT's rows with the exponential
# law and the N column's scaling identity in V (test_core_exact_law), central
# differences of the solver and the gap grid's path (the _jacobian test).
EXACT_LAW = ["test_core_exact_law", "test_core_exact_law_jacobian"]
MUTANTS += [
    dict(id="exact-law-local-slope", what="the local Jacobian under a law drops the law's slope",
         file="core/exact/local_friction.cpp",
         old="    const double m11 = f * (1.0 - ex * ex) + dh * ex * ex;",
         new="    const double m11 = f * (1.0 - ex * ex);", tests=EXACT_LAW, require=EXACT_LAW),
    dict(id="exact-law-speed-source", what="the slip speed's source misses sigma (dh/dsigma, "
         "not dh/dln sigma)", file="core/exact/local_friction.cpp",
         old="    out.speed_source = r.sigma * r.dh;", new="    out.speed_source = r.dh;",
         tests=EXACT_LAW, require=EXACT_LAW),
    dict(id="exact-law-slip-unit", what="the law's argument the normalised slip times V, without "
         "the slip's unit", file="core/exact/exact_law.hpp",
         old="        LocalLaw local{law_, law_.coefficient(0.0), V_ * slip_scale, FrictionMemory{}, 0.0, 0.0};",
         new="        LocalLaw local{law_, law_.coefficient(0.0), V_, FrictionMemory{}, 0.0, 0.0};",
         tests=EXACT_LAW, require=EXACT_LAW),
]
# The interface layer in the exact model (steady_rolling's operator,
# exact_model's compliance and yield, the solver's refusal): CONTACT's rows
# with the elastic layer and the plastic surface, central differences of
# the Jacobian, the refusals (test_core_exact_layer, test_capi_exact_layer).
LAYER = ["test_core_exact_layer", "test_capi_exact_layer"]
MUTANTS += [
    dict(id="layer-ahead", what="the layer's compliance couples to the element ahead with the "
         "wrong sign", file="core/exact/steady_rolling.cpp",
         old="            s[k] += layer_ * (v[k] - ahead);",
         new="            s[k] += layer_ * (v[k] + ahead);", tests=LAYER, require=LAYER),
    dict(id="layer-own-diagonal", what="the sweep's own coefficient misses the layer",
         file="core/exact/steady_rolling.cpp",
         old="    b0x_ += layer_;", new="    b0x_ += 0.0;", tests=LAYER, require=LAYER),
    dict(id="layer-element-length", what="the layer's compliance per element width, not length",
         file="core/exact/exact_model.cpp",
         old="    s.layer = in.layer_h > 0.0 ? in.layer_h / in.layer_G * in.G / s.dx : 0.0;",
         new="    s.layer = in.layer_h > 0.0 ? in.layer_h / in.layer_G * in.G / s.dy : 0.0;",
         tests=LAYER, require=LAYER),
    dict(id="layer-yield-unit", what="the yield stress over p0, not over mu p0",
         file="core/exact/exact_model.cpp",
         old="    s.yield = in.tau_c0 > 0.0 && s.traction_scale > 0.0 ? in.tau_c0 / s.traction_scale : 0.0;",
         new="    s.yield = in.tau_c0 > 0.0 && s.traction_scale > 0.0 ? in.tau_c0 / s.p0 : 0.0;",
         tests=LAYER, require=LAYER),
    dict(id="layer-yield-jacobian-N", what="the N column ignores that tau_c does not grow with N",
         file="core/exact/exact_jacobian.cpp",
         old="        if (s.yield > 0.0) euler -= frame[r] * T * area * dS_yield[r];",
         new="        (void)dS_yield;", tests=LAYER, require=LAYER),
    dict(id="layer-refusal", what="a model without the layer ignores it silently",
         file="core/solver.cpp",
         old="        if (!m.takes_interface_layer())",
         new="        if (false && !m.takes_interface_layer())", tests=LAYER, require=LAYER),
    # Hardening and softening (k_tau != 0): the yield stress carried along
    # each row, its chain in the linearisation, its N column.
    dict(id="yield-not-carried", what="every element starts from tau_c0, not the yield stress "
         "ahead", file="core/exact/steady_rolling.cpp",
         old="                tau = y.tau;", new="                (void)y.tau;",
         tests=LAYER, require=LAYER),
    dict(id="yield-slope-length", what="k_tau dx / G per element width, not length",
         file="core/exact/exact_model.cpp",
         old="    s.yield_k = s.yield > 0.0 ? in.k_tau * s.dx / in.G : 0.0;",
         new="    s.yield_k = s.yield > 0.0 ? in.k_tau * s.dy / in.G : 0.0;",
         tests=LAYER, require=LAYER),
    dict(id="yield-hardening-uncapped", what="a hardening yield stress passes mu p",
         file="core/exact/local_friction.hpp",
         old="        if (k > 0.0) return v < g ? YieldValue{v, k, 1.0, 0.0} : YieldValue{g, 0.0, 0.0, 0.0};",
         new="        if (k > 0.0) return YieldValue{v, k, 1.0, 0.0};",
         tests=LAYER, require=LAYER),
    dict(id="yield-chain-flow", what="the linearised chain drops the flow's share of the yield "
         "stress", file="core/exact/steady_rolling.cpp",
         old="    dtau = y.h_phi * dphi + dh;", new="    dtau = 0.0 * dphi + dh;",
         tests=LAYER, require=LAYER),
    dict(id="yield-jacobian-N", what="the N column misses tau_c0's share under hardening",
         file="core/exact/steady_rolling.cpp",
         old="        double dtau = yield ? tau0_ : 0.0;", new="        double dtau = 0.0;",
         tests=LAYER, require=LAYER),
]
# Friction memory in the exact models (core/exact/steady_memory.cpp):
# CONTACT's rows with MEMDST 3 um, the recurrence read back from the fields
# (test_core_exact_memory), and CONTACT's rows through the C ABI on both
# grids (test_capi_exact_law).
EXACT_MEMORY = ["test_core_exact_memory", "test_capi_exact_law"]
MUTANTS += [
    dict(id="exact-memory-leading-edge", what="memory starts each row from mu = 0, not the "
         "static coefficient", file="core/exact/steady_memory.cpp",
         old="        double ahead = mu_static;", new="        double ahead = 0.0;",
         tests=EXACT_MEMORY, require=EXACT_MEMORY),
    dict(id="exact-memory-slip-speed", what="the memory pass takes every element as adhering "
         "(theta at s0)", file="core/exact/steady_memory.cpp",
         old="            const double sigma = state_[k] == 2 ? std::abs(s_[k]) : 0.0;",
         new="            const double sigma = 0.0;",
         tests=EXACT_MEMORY, require=EXACT_MEMORY),
]
# The exact models' Jacobian under memory (the chain along each row in the
# tangents): central differences of the solver (test_core_exact_law_jacobian)
# and through the C ABI on both grids (test_capi_exact_law).
EXACT_MEMORY_JACOBIAN = ["test_core_exact_law_jacobian", "test_capi_exact_law"]
MUTANTS += [
    dict(id="exact-memory-chain-bound", what="the tangents drop the bound's change with the "
         "coefficient ahead", file="core/exact/steady_memory.cpp",
         old="    d += slip_info_[k].u * (l.bound * dmu);", new="",
         tests=EXACT_MEMORY_JACOBIAN, require=EXACT_MEMORY_JACOBIAN),
    dict(id="exact-memory-chain-theta", what="the chain forgets the coefficient ahead (theta)",
         file="core/exact/steady_memory.cpp",
         old="    dmu = l.theta * dmu + l.dmu_dsigma * (dsigma + (speed ? l.sigma : 0.0));",
         new="    dmu = l.dmu_dsigma * (dsigma + (speed ? l.sigma : 0.0));",
         tests=EXACT_MEMORY_JACOBIAN, require=EXACT_MEMORY_JACOBIAN),
]
# The exact models' law through the doors: mu_min, mu_max against the law
# at the exported slip speeds, and a Coulomb solve after a law's on one
# handle against a fresh handle's (C ABI, Python; the CLI, one solve per
# run, the range only).
EXACT_LAW_DOORS = ["test_capi_exact_law", "python_test_friction",
                   "cli_exact_law_json_matches_library"]
MUTANTS += [
    dict(id="exact-law-range", what="the exact models report mu_max as mu_min",
         file="core/exact/exact_law.hpp",
         old="        mu_min = info.mu_min;", new="        mu_min = info.mu_max;",
         tests=EXACT_LAW_DOORS),
    dict(id="exact-law-clear-warm", what="a Coulomb solve after a law's starts warm from the "
         "law's solution", file="core/exact/exact_model.hpp",
         old="        if (law_.clear()) has_previous_ = false;", new="        law_.clear();",
         tests=EXACT_LAW_DOORS[:2]),
]
# The friction law through the doors: CONTACT's tractcurv rows and Polach's
# closed form through the C ABI, Python, Fortran, the CLI and campaigns.
FRICTION_DOORS = [
    "test_capi_friction", "python_test_friction", "test_fortran_friction",
    "cli_friction_json_matches_library", "campaign_friction_rows_match_library",
]
MUTANTS += [
    dict(id="friction-route-swapped", what="the local and the global slip speed's routes swapped",
         file="core/solver.cpp",
         old="    return in.friction_speed == FrictionSpeed::global ? ModelKind::fastsim_global_slip",
         new="    return in.friction_speed != FrictionSpeed::global ? ModelKind::fastsim_global_slip",
         tests=FRICTION_DOORS),
    dict(id="friction-translate-half-speed", what="the C ABI reads s_h2 for s_h1",
         file="capi/capi_translate.cpp",
         old="    in.s_h1 = p.s_h1;", new="    in.s_h1 = p.s_h2;", tests=FRICTION_DOORS),
    dict(id="friction-polach-mu", what="cw_friction_polach writes (1 - A) mu0 as mu",
         file="capi/capi_helpers.cpp",
         old="        params->mu = law.mu_kin;", new="        params->mu = law.mu_e1;",
         tests=FRICTION_DOORS),
    dict(id="friction-half-speed-rule", what="the half-speed rule reads s_h2 for s_h1",
         file="core/contact/plausibility.cpp",
         old='    {CheckRule::half_speed, "s_h1", "m/s", kHalfSpeed, [](const C& c) { return c.s_h1; },',
         new='    {CheckRule::half_speed, "s_h1", "m/s", kHalfSpeed, [](const C& c) { return c.s_h2; },',
         tests=["test_capi_friction", "python_test_friction"]),
]
# -------------------------------------------------------------- end friction

def run(cmd, cwd=None, quiet=True):
    r = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE if quiet else None,
                       stderr=subprocess.STDOUT if quiet else None, text=True)
    return r.returncode, (r.stdout or "")


def copy_tree(src, dst):
    """Tracked and untracked-but-not-ignored files: the working tree as it is."""
    _, out = run(["git", "ls-files", "-co", "--exclude-standard", "-z"], cwd=src)
    for rel in filter(None, out.split("\0")):
        s = os.path.join(src, rel)
        if not os.path.isfile(s):
            continue
        d = os.path.join(dst, rel)
        os.makedirs(os.path.dirname(d), exist_ok=True)
        shutil.copy2(s, d)


def targets_of(build, tests):
    """Executables the tests run (basenames of their commands that are targets)."""
    _, out = run(["cmake", "--build", build, "--target", "help"])
    known = set(re.findall(r"^\.\.\. (\S+)", out, re.M))
    _, js = run(["ctest", "--test-dir", build, "--show-only=json-v1"])
    info = {t["name"]: t.get("command", []) for t in json.loads(js)["tests"]}
    targets = set()
    for name in tests:
        if name not in info:
            sys.exit(f"mutation-check: no CTest test named {name}")
        found = False
        for word in info[name]:
            base = os.path.basename(word)
            base = "creepwork_cli" if base == "creepwork" else base
            if base in known:
                targets.add(base)
                found = True
        if not found:
            targets.add("all")
    return sorted(targets)


def build(build_dir, targets, jobs):
    cmd = ["cmake", "--build", build_dir, "-j", str(jobs)]
    if "all" not in targets:
        for t in targets:
            cmd += ["--target", t]
    return run(cmd)


def failed_tests(build_dir, tests, jobs):
    regex = "^(" + "|".join(re.escape(t) for t in tests) + ")$"
    _, out = run(["ctest", "--test-dir", build_dir, "-j", str(jobs), "--timeout", "300", "-R", regex])
    failed = re.findall(r"^\s*\d+ - (\S+) \(", out, re.M)
    ran = re.findall(r"Test\s+#\d+: (\S+) \.", out)
    return set(failed), set(ran)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--only", nargs="*", help="mutant ids")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--keep", action="store_true", help="keep the temporary copy")
    ap.add_argument("--all-tests", action="store_true",
                    help="run every CTest test per mutant (slow; shows every catcher)")
    ap.add_argument("--check-targets", action="store_true",
                    help="only check that every mutant's edit applies to exactly one line "
                         "(no build; CTest runs this so that a refactor cannot orphan a mutant)")
    args = ap.parse_args()
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    mutants = [m for m in MUTANTS if not args.only or m["id"] in args.only]
    if args.check_targets:
        stale = [m["id"] for m in mutants
                 if open(os.path.join(root, m["file"])).read().count(m["old"]) != 1
                 or "\n" in m["old"] or "\n" in m["new"] or m["old"] == m["new"]]
        for i in stale:
            print(f"mutant {i}: its edit does not apply to exactly one line", file=sys.stderr)
        print(f"{len(mutants) - len(stale)} of {len(mutants)} mutants apply")
        sys.exit(1 if stale else 0)

    tmp = tempfile.mkdtemp(prefix="creepwork-mutation-")
    src, bld = os.path.join(tmp, "src"), os.path.join(tmp, "build")
    try:
        copy_tree(root, src)
        rc, out = run(["cmake", "-S", src, "-B", bld, "-DCMAKE_BUILD_TYPE=Release",
                       "-DCREEPWORK_BUILD_BENCH=OFF"])
        if rc:
            sys.exit(out)
        if args.all_tests:
            _, js = run(["ctest", "--test-dir", bld, "--show-only=json-v1"])
            everything = [t["name"] for t in json.loads(js)["tests"]]
            for m in mutants:
                m["tests"] = everything
        union = sorted({t for m in mutants for t in m["tests"]})
        print(f"building the copy in {tmp} ...", file=sys.stderr)
        rc, out = build(bld, targets_of(bld, union), args.jobs)
        if rc:
            sys.exit(out[-3000:])
        failed, _ = failed_tests(bld, union, args.jobs)
        if failed:
            sys.exit("mutation-check: unmutated tests fail: " + ", ".join(sorted(failed)))

        rows, bad = [], 0
        for m in mutants:
            path = os.path.join(src, m["file"])
            text = open(path).read()
            if text.count(m["old"]) != 1 or "\n" in m["old"] or "\n" in m["new"]:
                rows.append((m, None, "edit does not apply to exactly one line"))
                bad += 1
                continue
            print(f"mutant {m['id']} ...", file=sys.stderr)
            open(path, "w").write(text.replace(m["old"], m["new"]))
            try:
                rc, out = build(bld, targets_of(bld, m["tests"]), args.jobs)
                if rc:
                    rows.append((m, None, "does not compile"))
                    bad += 1
                    continue
                caught, ran = failed_tests(bld, m["tests"], args.jobs)
                missing = set(m["tests"]) - ran
                need = m.get("min_caught", 2)
                verdict = "ok"
                if missing:
                    verdict = "tests did not run: " + ", ".join(sorted(missing))
                elif len(caught) < need:
                    verdict = f"caught by {len(caught)} < {need} tests"
                elif not set(m.get("require", [])) <= caught:
                    verdict = "not caught by " + ", ".join(sorted(set(m["require"]) - caught))
                bad += verdict != "ok"
                rows.append((m, caught, verdict))
            finally:
                open(path, "w").write(text)
        # Leave the copy's build matching its sources.
        build(bld, targets_of(bld, union), args.jobs)

        print("| mutant | edit | caught by | candidates that passed | verdict |")
        print("|---|---|---|---|---|")
        for m, caught, verdict in rows:
            edit = f"`{m['file']}`: {m['what']}"
            c = ", ".join(sorted(caught)) if caught else "-"
            passed = ", ".join(sorted(set(m["tests"]) - (caught or set()))) if caught is not None else "-"
            print(f"| {m['id']} | {edit} | {c} | {passed} | {verdict} |")
        return 1 if bad else 0
    finally:
        if args.keep:
            print(f"copy kept in {tmp}", file=sys.stderr)
        else:
            shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
