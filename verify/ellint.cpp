// `disklab ellint`: one Legendre elliptic integral, ours and (with --json) Boost.Math's.
//
//   disklab ellint f  (--phi PHI | --complete) --m M [--one-minus-m MC] [--json]
//   disklab ellint pi --n N (--phi PHI | --complete) --m M [--one-minus-n NC] [--one-minus-m MC]
//                     [--json]
//
// Convention (docs/design.md section 3): F(phi|m) = int_0^phi dt / sqrt(1 - m sin^2 t),
// Pi(n; phi|m) = int_0^phi dt / ((1 - n sin^2 t) sqrt(1 - m sin^2 t)). Any finite phi is
// accepted: the library reduces it (odd, I(phi + j pi) = I(phi) + 2j I(pi/2); elliptic_legendre.h,
// Boost.Math's semantics). --complete asks for K(m) = F(pi/2|m) or Pi(n|m) at exactly pi/2,
// computed as the complete integrals (not at fl(pi/2), 6.1e-17 below it). Boost's ellint_1 and
// ellint_3 take the modulus k = sqrt(m); --json reports Boost with the double policy
// (promote_double<false>, computes in double) and the default policy (promotes to long double),
// each with its distance in ulps from our value (their complete forms with --complete).
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_3.hpp>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "command.h"
#include "common/args.h"
#include "common/output.h"
#include "disklab/math/elliptic.h"
#include "reference_csv.h"

namespace disklab::cli {
namespace {

using boost_double_policy =
    boost::math::policies::policy<boost::math::policies::promote_double<false>>;

struct EllintState {
  std::string n, phi, m, one_minus_n, one_minus_m;
  bool json = false, complete = false;
};

// Signed distance in representable doubles (both finite).
using reference::ulp_distance;

// Boost's value (or its error message) next to ours.
template <class Eval>
nlohmann::json boost_entry(Eval eval, double own, const char* policy) {
  nlohmann::json j;
  j["policy"] = policy;
  try {
    const double v = eval();
    j["value"] = v;
    if (std::isfinite(v) && std::isfinite(own))
      j["ulp_own_minus_boost"] = ulp_distance(own, v);
    else
      j["ulp_own_minus_boost"] = nullptr;
  } catch (const std::exception& e) {
    j["value"] = nullptr;
    j["error"] = e.what();
  }
  return j;
}

struct Inputs {
  double n = 0, one_minus_n = 1, phi = 0, m = 0, one_minus_m = 1;
};

Inputs parse_inputs(const EllintState& s, bool with_n) {
  Inputs in;
  // CLI11 rejects --phi together with --complete; one of them is needed.
  if (!s.complete) {
    if (s.phi.empty()) throw UsageError("--phi or --complete is required");
    in.phi = parse_double(s.phi, "--phi");  // any finite value (non-finite: usage error)
  }
  in.m = parse_double(s.m, "--m");
  if (!(in.m >= 0.0 && in.m < 1.0)) throw UsageError("--m: " + s.m + " is outside [0, 1)");
  in.one_minus_m =
      s.one_minus_m.empty() ? 1.0 - in.m : parse_double(s.one_minus_m, "--one-minus-m");
  if (!(in.one_minus_m > 0.0 && in.one_minus_m <= 1.0))
    throw UsageError("--one-minus-m: " + s.one_minus_m + " is outside (0, 1]");
  if (std::fabs((1.0 - in.m) - in.one_minus_m) > 1e-15)
    throw UsageError("--one-minus-m: " + s.one_minus_m + " is not 1 - m for --m " + s.m);
  if (with_n) {
    in.n = parse_double(s.n, "--n");
    if (!(in.n < 1.0)) throw UsageError("--n: " + s.n + " must be below 1");
    in.one_minus_n =
        s.one_minus_n.empty() ? 1.0 - in.n : parse_double(s.one_minus_n, "--one-minus-n");
    if (!(in.one_minus_n > 0.0)) throw UsageError("--one-minus-n: must be positive");
    if (std::fabs((1.0 - in.n) - in.one_minus_n) > 1e-15 * std::fabs(1.0 - in.n))
      throw UsageError("--one-minus-n: " + s.one_minus_n + " is not 1 - n for --n " + s.n);
  }
  return in;
}

double own_value(const Inputs& in, bool pi, bool complete) {
  if (complete)
    return pi ? math::ellint_pi_complete(in.n, in.one_minus_n, in.m, in.one_minus_m)
              : math::ellint_k(in.m, in.one_minus_m);
  return pi ? math::ellint_pi(in.n, in.one_minus_n, in.phi, in.m, in.one_minus_m)
            : math::ellint_f(in.phi, in.m, in.one_minus_m);
}

int run(const EllintState& s, bool pi) {
  const Inputs in = parse_inputs(s, pi);
  const double own = own_value(in, pi, s.complete);
  if (!s.json) {
    std::printf("%s\n", fmt17(own).c_str());
    return 0;
  }
  const double k = std::sqrt(in.m);
  nlohmann::json j;
  j["function"] = pi ? "pi" : "f";
  j["convention"] = pi ? "Pi(n;phi|m) = int_0^phi dt/((1-n sin^2 t) sqrt(1-m sin^2 t))"
                       : "F(phi|m) = int_0^phi dt/sqrt(1-m sin^2 t)";
  j["complete"] = s.complete;  // true: phi = pi/2 exactly (K(m) or Pi(n|m))
  if (pi) j["n"] = in.n;
  j["phi"] = s.complete ? nlohmann::json(nullptr) : nlohmann::json(in.phi);
  j["m"] = in.m;
  j["one_minus_m"] = in.one_minus_m;
  if (pi) j["one_minus_n"] = in.one_minus_n;
  j["value"] = own;
  j["boost_k"] = k;  // Boost takes the modulus k = sqrt(m), rounded: part of Boost's error
  constexpr const char* kDoublePolicy = "promote_double<false> (double arithmetic)";
  constexpr const char* kDefaultPolicy = "default (promotes double to long double)";
  // Boost's complete forms for --complete: ellint_1(k), ellint_3(k, n).
  if (pi && s.complete) {
    j["boost_double_policy"] = boost_entry(
        [&] { return boost::math::ellint_3(k, in.n, boost_double_policy()); }, own, kDoublePolicy);
    j["boost_default_policy"] =
        boost_entry([&] { return boost::math::ellint_3(k, in.n); }, own, kDefaultPolicy);
  } else if (pi) {
    j["boost_double_policy"] =
        boost_entry([&] { return boost::math::ellint_3(k, in.n, in.phi, boost_double_policy()); },
                    own, kDoublePolicy);
    j["boost_default_policy"] =
        boost_entry([&] { return boost::math::ellint_3(k, in.n, in.phi); }, own, kDefaultPolicy);
  } else if (s.complete) {
    j["boost_double_policy"] = boost_entry(
        [&] { return boost::math::ellint_1(k, boost_double_policy()); }, own, kDoublePolicy);
    j["boost_default_policy"] =
        boost_entry([&] { return boost::math::ellint_1(k); }, own, kDefaultPolicy);
  } else {
    j["boost_double_policy"] =
        boost_entry([&] { return boost::math::ellint_1(k, in.phi, boost_double_policy()); }, own,
                    kDoublePolicy);
    j["boost_default_policy"] =
        boost_entry([&] { return boost::math::ellint_1(k, in.phi); }, own, kDefaultPolicy);
  }
  std::printf("%s\n", j.dump(2).c_str());
  return 0;
}

const Registrar kEllint{Command{
    "ellint",
    "Legendre elliptic integrals F(phi|m) and Pi(n;phi|m) (parameter m, not modulus k)",
    [](Options& sub) {
      auto state = std::make_shared<EllintState>();
      auto selected = std::make_shared<bool>(false);  // true: pi
      sub.require_subcommand(1);
      Options* f = sub.add_subcommand("f", "F(phi|m) = int_0^phi dt / sqrt(1 - m sin^2 t)");
      Options* p = sub.add_subcommand(
          "pi", "Pi(n;phi|m) = int_0^phi dt / ((1 - n sin^2 t) sqrt(1 - m sin^2 t))");
      for (Options* c : {f, p}) {
        Option* phi = c->add_option(
            "--phi", state->phi,
            "Amplitude: any finite real (outside [0, pi/2] reduced: the integral is odd and "
            "I(phi + j pi) = I(phi) + 2j I(pi/2))");
        c->add_flag("--complete", state->complete,
                    "The complete integral, K(m) or Pi(n|m), at exactly pi/2 (not fl(pi/2)); "
                    "instead of --phi")
            ->excludes(phi);
        c->add_option("--m", state->m, "Parameter m = k^2 in [0, 1)")->required();
        c->add_option("--one-minus-m", state->one_minus_m,
                      "1 - m, if known more accurately than the subtraction (m near 1)");
        c->add_flag(
            "--json", state->json,
            "JSON with Boost.Math's values (double and default policy) and ulp differences");
      }
      p->add_option("--n", state->n, "Characteristic n < 1 (any negative value)")->required();
      p->add_option("--one-minus-n", state->one_minus_n, "1 - n, if known more accurately");
      f->callback([selected] { *selected = false; });
      p->callback([selected] { *selected = true; });
      sub.footer(
          "Examples:\n"
          "  disklab ellint f --phi 1.2 --m 0.5\n"
          "  disklab ellint f --phi -40 --m 0.5     # any phi: F(-40|m) = -(24 K(m) + F(40 - 12 "
          "pi|m))\n"
          "  disklab ellint pi --n -1e8 --phi 1.5 --m 0.99 --json\n"
          "  disklab ellint pi --n 0.999 --one-minus-n 0.001 --phi 1.5707963267948966 --m 0.5\n"
          "  disklab ellint pi --complete --n 0.999 --one-minus-n 0.001 --m 0.5 --json\n"
          "  disklab ellint f --complete --m 0.999999 --one-minus-m 1.0000000000287557e-06\n"
          "--complete gives K(m) = F(pi/2|m) and Pi(n|m) = Pi(n;pi/2|m) at exactly pi/2: "
          "1.5707963267948966\n"
          "is fl(pi/2), 6.1e-17 below it, which near n, m -> 1 changes Pi by many ulps.\n"
          "Convention: F(phi|m) = int_0^phi dt/sqrt(1 - m sin^2 t); Boost's ellint_1/ellint_3 "
          "take\n"
          "k = sqrt(m). Out-of-domain input (m >= 1, n >= 1, non-finite phi) exits 2.");
      return [state, selected] { return run(*state, *selected); };
    },
    {}}};

}  // namespace
}  // namespace disklab::cli
