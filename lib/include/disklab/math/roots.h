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
#include <utility>

namespace disklab::math {

struct RootResult {
  double x = 0.0;      // the root estimate, always inside the initial bracket
  int iterations = 0;  // evaluations of g performed
  bool converged = false;
  bool stepped = false;  // x is one step past the last evaluation (not evaluated itself)
};

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
    if (newton_ok && final_step(x, next - x)) {
      out.x = next;
      out.converged = out.stepped = true;
      return out;
    }
    if (!newton_ok) next = 0.5 * (lo + hi);
    const double step = std::abs(next - x);
    x = next;
    if (step <= x_tol || !(lo < hi) || std::nextafter(lo, hi) >= hi) {
      out.x = x;
      out.converged = out.stepped = true;
      return out;
    }
  }
  out.x = x;
  out.converged = false;
  out.stepped = true;
  return out;
}

template <class Eval>
RootResult safeguarded_newton(Eval&& eval, double lo, double hi, double x0, double f_tol,
                              double x_tol, int max_iter = 64) {
  return safeguarded_newton(std::forward<Eval>(eval), lo, hi, x0, f_tol, x_tol, max_iter,
                            [](double, double) { return false; });
}

}  // namespace disklab::math
