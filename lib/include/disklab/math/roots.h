#pragma once
// Safeguarded Newton-Raphson for monotone increasing functions on a bracket.
//
// Used to invert the cumulative solid angle of the spherical-ellipse maps (Guillén et al. 2017,
// eqs. 13 and 21), whose derivative is cheap and exact (2 h_p and 1 - h_r). Newton alone can
// overshoot near the ends of the bracket where the derivative vanishes (grazing ellipses, the
// rim of the parallel map); every step is therefore checked against a bracket that shrinks with
// each evaluation, and a bisection step replaces any Newton step that would leave it. The
// iterate never leaves [lo, hi], the result is always finite, and the number of evaluations is
// reported so callers and tests can record it.
#include <cmath>
#include <limits>
#include <utility>

namespace disklab::math {

struct RootResult {
  double x = 0.0;      // the root estimate, always inside the initial bracket
  int iterations = 0;  // evaluations of g performed
  bool converged = false;
  bool stepped = false;  // x is one step past the last evaluation (not evaluated itself)
};

namespace detail {
// `out` (its evaluations counted) ending one step past the last evaluation, at x.
inline RootResult stepped_result(RootResult out, double x, bool converged) {
  out.x = x;
  out.converged = converged;
  out.stepped = true;
  return out;
}
// Whether the search ends after stepping to x: a step below x_tol (where it counts), or a
// bracket down to adjacent doubles. Adjacent doubles are at most eps |lo| + the smallest
// subnormal apart: that cheap necessary test runs before nextafter.
inline bool search_ends(double step, bool step_counts, double x_tol, double lo, double hi) {
  if ((step_counts && step <= x_tol) || !(lo < hi)) return true;
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  constexpr double kTiny = std::numeric_limits<double>::denorm_min();
  if (!(hi - lo <= kEps * std::abs(lo) + kTiny)) return false;
  return std::nextafter(lo, hi) >= hi;
}
}  // namespace detail

// Solves g(x) = 0 for g increasing on [lo, hi] with g(lo) <= 0 <= g(hi) (not checked: with a
// wrong sign the iterate walks to the nearest end, which is the natural clamp).
// `eval(x)` returns {g(x), g'(x)}. Stops when |g| <= f_tol, when the Newton step is below
// x_tol, or when the bracket is down to adjacent doubles; after `max_iter` evaluations it
// returns the best iterate with converged = false.
// `final_step(x, delta)`, asked after each evaluation at x whose Newton step x + delta stays in
// the bracket, may declare that step final without evaluating at its end (e.g. by a bound on
// the residual from the curvature): the result is then x + delta with stepped = true.
template <class Eval, class FinalStep>
RootResult safeguarded_newton(Eval&& eval, double lo, double hi, double x0, double f_tol,
                              double x_tol, int max_iter, FinalStep&& final_step) {
  RootResult out;
  double x = (x0 >= lo && x0 <= hi) ? x0 : 0.5 * (lo + hi);
  for (int it = 1; it <= max_iter; ++it) {
    const auto [g, dg] = eval(x);
    out.iterations = it;
    if (!(std::abs(g) > f_tol)) {  // also catches NaN g: stop rather than wander
      out.x = x;
      out.converged = std::abs(g) <= f_tol;
      return out;
    }
    // Shrink the bracket with the sign information of this evaluation.
    if (g < 0.0) {
      lo = x;
    } else {
      hi = x;
    }
    double next = x - g / dg;
    const bool newton_ok = dg > 0.0 && std::isfinite(next) && next > lo && next < hi;
    if (newton_ok && final_step(x, next - x)) return detail::stepped_result(out, next, true);
    if (!newton_ok) next = 0.5 * (lo + hi);
    const double step = std::abs(next - x);
    x = next;
    if (detail::search_ends(step, true, x_tol, lo, hi)) return detail::stepped_result(out, x, true);
  }
  return detail::stepped_result(out, x, false);
}

template <class Eval>
RootResult safeguarded_newton(Eval&& eval, double lo, double hi, double x0, double f_tol,
                              double x_tol, int max_iter = 64) {
  return safeguarded_newton(std::forward<Eval>(eval), lo, hi, x0, f_tol, x_tol, max_iter,
                            [](double, double) { return false; });
}

// Derivatives of g at one point, for safeguarded_halley.
struct Derivatives3 {
  double g = 0.0, d1 = 0.0, d2 = 0.0, d3 = 0.0;
};

// The contract of safeguarded_newton for an increasing g on [lo, hi], with `eval(x)` returning
// g and its first three derivatives. Each step is Halley's, delta = dn / (1 + dn g2 / (2 g1))
// with dn = -g / g1 (cubic convergence; g1, g2, g3 the derivatives), or Newton's where that
// denominator is below 1/2, or a bisection where either would leave the shrinking bracket. A
// Halley step is final without an evaluation at its end when the residual that Halley's error
// term predicts there, g1 |C| |delta|^3 with C = g2^2 / (4 g1^2) - g3 / (6 g1) (the error
// e_{k+1} = C e_k^3 to leading order), is below f_tol / 8 and the step below 1e-4 of the initial
// bracket (so that a C that happens to vanish at x cannot end the search early): such steps are
// below ~1e-5 of the function's scale, where the next order is smaller again by about as much.
// Halley's rule for a final step (see safeguarded_halley): `e` at x, `delta` Halley's step from
// it, `bracket` the initial bracket's width.
inline bool halley_step_is_final(const Derivatives3& e, double delta, double bracket,
                                 double f_tol) {
  const double ad = std::abs(delta);
  if (!(ad <= 1e-4 * bracket)) return false;
  // g1 |C| |delta|^3 <= f_tol / 8, multiplied through by g1 > 0 (no division).
  const double g1c = std::abs(0.25 * e.d2 * e.d2 - e.d3 * e.d1 / 6.0);
  return g1c * ad * ad * ad <= 0.125 * f_tol * e.d1;
}

// The step from a point with g1 > 0: Halley's, delta = dn / (1 + dn g2 / (2 g1)) with dn = -g /
// g1, or Newton's dn where that denominator is below 1/2 (`halley` says which). Multiplied
// through by g1^2, delta = -g g1 / (g1^2 - g g2 / 2): one division instead of two on the
// solve's critical path; where g1^2 could leave double's range, the two divisions.
struct HalleyStep {
  double delta = 0.0;
  bool halley = false;
};
inline HalleyStep halley_step(const Derivatives3& e) {
  const double g1 = e.d1;
  if (g1 >= 0x1p-400 && g1 <= 0x1p400) {
    const double g1sq = g1 * g1, den = g1sq - 0.5 * e.g * e.d2;
    const bool halley = den >= 0.5 * g1sq;
    return {-e.g * (halley ? g1 : 1.0) / (halley ? den : g1), halley};
  }
  const double inv_d1 = 1.0 / g1;
  const double dn = -e.g * inv_d1, denom = 1.0 + 0.5 * dn * e.d2 * inv_d1;
  const bool halley = denom >= 0.5;
  return {halley ? dn / denom : dn, halley};
}

template <class Eval>
RootResult safeguarded_halley(Eval&& eval, double lo, double hi, double x0, double f_tol,
                              double x_tol, int max_iter) {
  RootResult out;
  double x = (x0 >= lo && x0 <= hi) ? x0 : 0.5 * (lo + hi);
  const double bracket = hi - lo;
  for (int it = 1; it <= max_iter; ++it) {
    const Derivatives3 e = eval(x);
    out.iterations = it;
    if (!(std::abs(e.g) > f_tol)) {  // also catches NaN g: stop rather than wander
      out.x = x;
      out.converged = std::abs(e.g) <= f_tol;
      return out;
    }
    if (e.g < 0.0) {
      lo = x;
    } else {
      hi = x;
    }
    double next = 0.5 * (lo + hi);
    bool in_bracket = false;
    if (e.d1 > 0.0) {
      const auto [delta, halley] = halley_step(e);
      const double candidate = x + delta;
      if (std::isfinite(candidate) && candidate > lo && candidate < hi) {
        in_bracket = true;
        next = candidate;
        if (halley && halley_step_is_final(e, delta, bracket, f_tol))
          return detail::stepped_result(out, next, true);
      }
    }
    const double step = std::abs(next - x);
    x = next;
    if (detail::search_ends(step, in_bracket, x_tol, lo, hi))
      return detail::stepped_result(out, x, true);
  }
  return detail::stepped_result(out, x, false);
}

}  // namespace disklab::math
