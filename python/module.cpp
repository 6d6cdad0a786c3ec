// disklab's Python core, the extension module disklab._disklab: loops over numpy arrays that
// call the library, with the GIL released inside them. python/disklab/__init__.py is the API:
// it checks shapes, dtypes and geometry, broadcasts, and names the argument in every error.
// The functions here check shapes again (ValueError), so a direct caller cannot crash them.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "disklab/disk/strategy.h"
#include "disklab/ellipse/any_map.h"
#include "disklab/ellipse/solid_angle.h"
#include "disklab/math/elliptic.h"
#include "disklab/sequence/discrepancy.h"
#include "disklab/sequence/sequence.h"
#include "disklab/sequence/tabulated.h"

namespace py = pybind11;

namespace disklab::python {
namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
using BoolArray = py::array_t<bool, py::array::c_style>;
using IntArray = py::array_t<int32_t, py::array::c_style>;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The rows of a (n, cols) array; ValueError naming `what` for any other shape.
py::ssize_t rows_of(const Array& a, py::ssize_t cols, const char* what) {
  if (a.ndim() != 2 || a.shape(1) != cols)
    throw py::value_error(std::string(what) + ": expected an array of shape (n, " +
                          std::to_string(cols) + ")");
  return a.shape(0);
}

Array new_array(py::ssize_t n, py::ssize_t cols) {
  return cols == 0 ? Array({n}) : Array({n, cols});
}

Point2 point2_at(const double* p, py::ssize_t i) {
  return {p[2 * i], p[2 * i + 1]};
}
Vec3 vec3_at(const double* p, py::ssize_t i) {
  return {p[3 * i], p[3 * i + 1], p[3 * i + 2]};
}
void store(double* out, py::ssize_t i, Point2 v) {
  out[2 * i] = v.x;
  out[2 * i + 1] = v.y;
}
void store(double* out, py::ssize_t i, const Vec3& v) {
  out[3 * i] = v.x();
  out[3 * i + 1] = v.y();
  out[3 * i + 2] = v.z();
}

// u in the closed unit square (NaN is not).
bool in_unit_square(Point2 u) {
  return u.x >= 0.0 && u.x <= 1.0 && u.y >= 0.0 && u.y <= 1.0;
}

// ---- sequences ----

class PySequence {
 public:
  PySequence(const std::string& name, uint64_t seed, std::optional<uint32_t> capacity)
      : seed_(seed) {
    py::gil_scoped_release unlocked;  // best-candidate and pmj02bn tables take a while
    seq_ = capacity ? sequence::make_sequence(name, seed, *capacity)
                    : sequence::make_sequence(name, seed);
  }
  std::string name() const { return std::string(seq_->name()); }
  uint64_t seed() const { return seed_; }

  Array points(uint32_t first, uint32_t count) const {
    Array out = new_array(count, 2);
    auto* p = reinterpret_cast<Point2*>(out.mutable_data());
    static_assert(sizeof(Point2) == 2 * sizeof(double));
    py::gil_scoped_release unlocked;
    seq_->fill(first, std::span<Point2>(p, count));
    return out;
  }
  Array at(const py::array_t<uint32_t, py::array::c_style | py::array::forcecast>& index) const {
    const py::ssize_t n = index.size();
    Array out = new_array(n, 2);
    const uint32_t* in = index.data();
    double* o = out.mutable_data();
    py::gil_scoped_release unlocked;
    for (py::ssize_t i = 0; i < n; ++i)
      store(o, i, seq_->at(in[i]));
    return out;
  }
  const sequence::Sequence& get() const { return *seq_; }

 private:
  std::unique_ptr<sequence::Sequence> seq_;
  uint64_t seed_;
};

// ---- disk strategies (Christensen 2018, Sec. 3) ----

class PyDiskStrategy {
 public:
  explicit PyDiskStrategy(const std::string& name) {
    const auto s = disk::parse_strategy(name);
    if (!s) {
      std::string valid;
      for (const auto& n : disk::strategy_names())
        valid += " " + n;
      throw py::value_error("name: unknown disk strategy '" + name + "' (valid:" + valid + ")");
    }
    s_ = *s;
  }
  std::string name() const { return std::string(disk::strategy_name(s_)); }
  uint32_t copies() const { return disk::copies_per_square_point(s_); }

  // Row copies*i + k is copy k of u[i] (the memo's sample s = 4i + k for the four-copy
  // strategies); pad-zero and rejection give the candidate 2u - 1 (see weights()).
  Array sample(const Array& u) const {
    const py::ssize_t n = rows_of(u, 2, "u");
    const uint32_t c = copies();
    Array out = new_array(n * c, 2);
    const double* in = u.data();
    double* o = out.mutable_data();
    py::gil_scoped_release unlocked;
    for (py::ssize_t i = 0; i < n; ++i) {
      const Point2 uv = point2_at(in, i);
      switch (s_) {
        case disk::Strategy::pad_zero:
        case disk::Strategy::rejection:
          store(o, i, disk::square_to_centered(uv));
          break;
        case disk::Strategy::polar:
          store(o, i, disk::sample_polar(uv));
          break;
        case disk::Strategy::concentric:
          store(o, i, disk::sample_concentric(uv));
          break;
        case disk::Strategy::polar4:
        case disk::Strategy::concentric4: {
          const auto four =
              s_ == disk::Strategy::polar4 ? disk::sample_polar4(uv) : disk::sample_concentric4(uv);
          for (uint32_t k = 0; k < 4; ++k)
            store(o, 4 * i + k, four[k]);
          break;
        }
      }
    }
    return out;
  }

  // Estimator weight of each row of sample(u): pad-zero 4/pi inside the disk and 0 outside,
  // rejection 1 for an accepted candidate and 0 for a rejected one, the maps 1.
  Array weights(const Array& u) const {
    const py::ssize_t n = rows_of(u, 2, "u");
    const uint32_t c = copies();
    Array out = new_array(n * c, 0);
    const double* in = u.data();
    double* o = out.mutable_data();
    py::gil_scoped_release unlocked;
    for (py::ssize_t i = 0; i < n; ++i) {
      const Point2 uv = point2_at(in, i);
      double w = 1.0;
      if (s_ == disk::Strategy::pad_zero) w = disk::sample_pad_zero(uv).weight;
      if (s_ == disk::Strategy::rejection) w = disk::try_rejection(uv).accepted ? 1.0 : 0.0;
      for (uint32_t k = 0; k < c; ++k)
        o[c * i + k] = w;
    }
    return out;
  }

  // The square point each disk point comes from, and which copy it is (0 but for the four-copy
  // strategies). NaN rows where there is none: pad-zero outside [-1, 1]^2, rejection outside the
  // disk; the maps clamp to the disk (their inverses accept any point).
  std::pair<Array, IntArray> invert(const Array& p) const {
    const py::ssize_t n = rows_of(p, 2, "p");
    Array out = new_array(n, 2);
    IntArray copy({n});
    const double* in = p.data();
    double* o = out.mutable_data();
    int32_t* k = copy.mutable_data();
    py::gil_scoped_release unlocked;
    for (py::ssize_t i = 0; i < n; ++i) {
      const Point2 q = point2_at(in, i);
      Point2 uv{kNaN, kNaN};
      k[i] = 0;
      const bool finite = std::isfinite(q.x) && std::isfinite(q.y);
      switch (s_) {
        case disk::Strategy::pad_zero:
          if (std::fabs(q.x) <= 1.0 && std::fabs(q.y) <= 1.0) uv = disk::centered_to_square(q);
          break;
        case disk::Strategy::rejection:
          if (disk::in_disk_exactly(q)) uv = disk::centered_to_square(q);
          break;
        case disk::Strategy::polar:
          if (finite) uv = disk::invert_polar(q);
          break;
        case disk::Strategy::concentric:
          if (finite) uv = disk::invert_concentric(q);
          break;
        case disk::Strategy::polar4:
        case disk::Strategy::concentric4:
          if (finite) {
            const disk::Inverse4 r =
                s_ == disk::Strategy::polar4 ? disk::invert_polar4(q) : disk::invert_concentric4(q);
            uv = r.uv;
            k[i] = static_cast<int32_t>(r.k);
          }
          break;
      }
      store(o, i, uv);
    }
    return {out, copy};
  }

  // Area density of the strategy's disk points (all copies together): 1/pi on the unit disk,
  // pad-zero's candidates 1/4 on [-1, 1]^2; 0 elsewhere.
  Array pdf(const Array& p) const {
    const py::ssize_t n = rows_of(p, 2, "p");
    Array out = new_array(n, 0);
    const double* in = p.data();
    double* o = out.mutable_data();
    py::gil_scoped_release unlocked;
    for (py::ssize_t i = 0; i < n; ++i) {
      const Point2 q = point2_at(in, i);
      if (s_ == disk::Strategy::pad_zero)
        o[i] = std::fabs(q.x) <= 1.0 && std::fabs(q.y) <= 1.0 ? 0.25 : 0.0;
      else
        o[i] = disk::in_disk_exactly(q) ? disk::kInvPi : 0.0;
    }
    return out;
  }

  // The memo's renderer walk (disk::DiskSampler): `count` disk samples from the sequence
  // starting at square point `first`, rejection skipping the points outside the disk. Returns
  // (square index, square point, disk point, weight), row s for sample s, as `disklab points
  // --strategy` prints them.
  py::tuple walk(const PySequence& seq, uint32_t count, uint32_t first) const {
    py::array_t<int64_t> index({static_cast<py::ssize_t>(count)});
    Array uv = new_array(count, 2), point = new_array(count, 2), weight = new_array(count, 0);
    int64_t* ix = index.mutable_data();
    double *pu = uv.mutable_data(), *pp = point.mutable_data(), *pw = weight.mutable_data();
    {
      py::gil_scoped_release unlocked;
      disk::DiskSampler<sequence::Sequence> sampler(s_, seq.get(), first);
      for (uint32_t s = 0; s < count; ++s) {
        const disk::DiskSample d = sampler.next();
        ix[s] = d.square_index;
        store(pu, s, d.uv);
        store(pp, s, d.point);
        pw[s] = d.weight;
      }
    }
    return py::make_tuple(index, uv, point, weight);
  }

 private:
  disk::Strategy s_ = disk::Strategy::polar;
};

// ---- spherical-ellipse maps (Guillen et al. 2017; ellipse/any_map.h) ----

ellipse::Disk make_disk(const Array& center, const Array& normal, double radius, bool two_sided) {
  if (center.size() != 3 || normal.size() != 3)
    throw py::value_error("center, normal: expected 3 numbers each");
  ellipse::Disk d;
  d.center = vec3_at(center.data(), 0);
  d.normal = vec3_at(normal.data(), 0);
  d.radius = radius;
  d.two_sided = two_sided;
  return d;
}

// The columns of sample(): rows that are no sample (u outside the closed unit square or NaN, or
// the map's valid == false) have zero direction, point and pdf.
struct Samples {
  Array direction, point, pdf;
  BoolArray valid;
  double *d, *p, *f;
  bool* v;
  explicit Samples(py::ssize_t n)
      : direction(new_array(n, 3)),
        point(new_array(n, 3)),
        pdf(new_array(n, 0)),
        valid({n}),
        d(direction.mutable_data()),
        p(point.mutable_data()),
        f(pdf.mutable_data()),
        v(valid.mutable_data()) {}
  void set(py::ssize_t i, const ellipse::EllipseSample& s, bool ok) {
    const bool keep = ok && s.valid;
    store(d, i, keep ? s.direction : Vec3::Zero());
    store(p, i, keep ? s.point : Vec3::Zero());
    f[i] = keep ? s.pdf : 0.0;
    v[i] = keep;
  }
  py::tuple tuple() const { return py::make_tuple(direction, point, pdf, valid); }
};

class PyEllipseMap {
 public:
  PyEllipseMap(const std::string& kind, const Array& center, const Array& normal, double radius,
               bool two_sided, const Array& o, const std::optional<Array>& receiver_normal) {
    const auto k = ellipse::parse_map(kind);
    if (!k) {
      std::string valid;
      for (const auto& n : ellipse::map_names())
        valid += " " + n;
      throw py::value_error("kind: unknown spherical-ellipse map '" + kind + "' (valid:" + valid +
                            ")");
    }
    if (o.size() != 3) throw py::value_error("o: expected 3 numbers");
    const ellipse::Disk d = make_disk(center, normal, radius, two_sided);
    const Vec3 p = vec3_at(o.data(), 0);
    if (receiver_normal) {
      if (receiver_normal->size() != 3)
        throw py::value_error("receiver_normal: expected 3 numbers");
      map_.emplace(ellipse::AnyMap::make(*k, d, p, vec3_at(receiver_normal->data(), 0)));
    } else {
      map_.emplace(ellipse::AnyMap::make(*k, d, p));
    }
  }
  const ellipse::AnyMap& map() const { return *map_; }

  py::tuple sample(const Array& u) const {
    const py::ssize_t n = rows_of(u, 2, "u");
    Samples out(n);
    const double* in = u.data();
    {
      py::gil_scoped_release unlocked;
      for (py::ssize_t i = 0; i < n; ++i) {
        const Point2 uv = point2_at(in, i);
        const bool ok = in_unit_square(uv);
        out.set(i, ok ? map_->sample(uv) : ellipse::EllipseSample{}, ok);
      }
    }
    return out.tuple();
  }

  // Row copies*i + k is copy k of u[i] (radial4's reflections; the others: sample(u)).
  py::tuple sample_copies(const Array& u) const {
    const py::ssize_t n = rows_of(u, 2, "u");
    const int c = map_->copies();
    Samples out(n * c);
    const double* in = u.data();
    {
      py::gil_scoped_release unlocked;
      std::array<ellipse::EllipseSample, 4> four;
      for (py::ssize_t i = 0; i < n; ++i) {
        const Point2 uv = point2_at(in, i);
        const bool ok = in_unit_square(uv);
        if (ok) map_->sample_copies(uv, four);
        for (int k = 0; k < c; ++k)
          out.set(c * i + k, ok ? four[k] : ellipse::EllipseSample{}, ok);
      }
    }
    return out.tuple();
  }

  Array pdf_of(const Array& directions) const {
    const py::ssize_t n = rows_of(directions, 3, "directions");
    Array out = new_array(n, 0);
    const double* in = directions.data();
    double* o = out.mutable_data();
    py::gil_scoped_release unlocked;
    for (py::ssize_t i = 0; i < n; ++i) {
      const Vec3 w = vec3_at(in, i);
      o[i] = w.allFinite() ? map_->pdf(w) : 0.0;
    }
    return out;
  }

  BoolArray contains(const Array& directions) const {
    const py::ssize_t n = rows_of(directions, 3, "directions");
    BoolArray out({n});
    const double* in = directions.data();
    bool* o = out.mutable_data();
    py::gil_scoped_release unlocked;
    for (py::ssize_t i = 0; i < n; ++i) {
      const Vec3 w = vec3_at(in, i);
      o[i] = w.allFinite() && map_->contains(w);
    }
    return out;
  }

  // (u, copy): u with sample_copies(u)[copy] along each direction; NaN and -1 where there is none.
  std::pair<Array, IntArray> invert(const Array& directions) const {
    const py::ssize_t n = rows_of(directions, 3, "directions");
    Array out = new_array(n, 2);
    IntArray copy({n});
    const double* in = directions.data();
    double* o = out.mutable_data();
    int32_t* k = copy.mutable_data();
    py::gil_scoped_release unlocked;
    for (py::ssize_t i = 0; i < n; ++i) {
      const Vec3 w = vec3_at(in, i);
      int c = -1;
      std::optional<Point2> u;
      if (w.allFinite()) u = map_->invert_copy(w, &c);
      store(o, i, u ? *u : Point2{kNaN, kNaN});
      k[i] = u ? c : -1;
    }
    return {out, copy};
  }

 private:
  std::optional<ellipse::AnyMap> map_;
};

// ---- integrals ----

// out[i] = f(a[i], b[i], ...) over arrays of one size (the caller broadcasts).
template <class F, class... A>
Array elementwise(F f, const A&... args) {
  const py::ssize_t n = std::get<0>(std::tie(args...)).size();
  if (((args.size() != n) || ...)) throw py::value_error("arguments: sizes differ");
  Array out = new_array(n, 0);
  double* o = out.mutable_data();
  const std::array<const double*, sizeof...(A)> in{args.data()...};
  py::gil_scoped_release unlocked;
  for (py::ssize_t i = 0; i < n; ++i)
    o[i] = [&]<std::size_t... I>(std::index_sequence<I...>) {
      return f(in[I][i]...);
    }
  (std::index_sequence_for<A...>{});
  return out;
}

Array solid_angles(const Array& center, const Array& normal, double radius, bool two_sided,
                   const Array& points) {
  const ellipse::Disk d = make_disk(center, normal, radius, two_sided);
  const py::ssize_t n = rows_of(points, 3, "points");
  Array out = new_array(n, 0);
  const double* in = points.data();
  double* o = out.mutable_data();
  py::gil_scoped_release unlocked;
  for (py::ssize_t i = 0; i < n; ++i)
    o[i] = ellipse::solid_angle(d, vec3_at(in, i));
  return out;
}

double l2_star(const Array& points) {
  const py::ssize_t n = rows_of(points, 2, "points");
  std::vector<Point2> p(static_cast<std::size_t>(n));
  const double* in = points.data();
  for (py::ssize_t i = 0; i < n; ++i)
    p[static_cast<std::size_t>(i)] = point2_at(in, i);
  py::gil_scoped_release unlocked;
  return sequence::l2_star_discrepancy(p);
}

// ---- the C++ loops the Python benchmark compares with (bench/python_ratios.py) ----

// What a C++ caller writes for the same samples: one sample per u, its direction, point, pdf
// and validity stored in arrays of its own (the columns sample() returns). Returns the seconds
// the loop took, allocation included, and a checksum of every field, so nothing is left unused.
std::pair<double, double> cpp_sample_loop(const PyEllipseMap& m, const Array& u) {
  const py::ssize_t n = rows_of(u, 2, "u");
  const double* in = u.data();
  py::gil_scoped_release unlocked;
  const auto start = std::chrono::steady_clock::now();
  const auto size = static_cast<std::size_t>(n);
  std::vector<Vec3> direction(size), point(size);
  std::vector<double> pdf(size);
  // bool, as numpy's: char stores may alias anything and would make this loop reload its pointers.
  const std::unique_ptr<bool[]> valid(new bool[size]());
  for (std::size_t i = 0; i < size; ++i) {
    const ellipse::EllipseSample s = m.map().sample(point2_at(in, static_cast<py::ssize_t>(i)));
    direction[i] = s.direction;
    point[i] = s.point;
    pdf[i] = s.pdf;
    valid[i] = s.valid;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  double sum = 0.0;
  for (std::size_t i = 0; i < size; ++i)
    sum += valid[i] ? direction[i].x() + point[i].y() + pdf[i] : 0.0;
  return {seconds, sum};
}

// The concrete pmj02 generator (no type erasure), built and read into a vector of points.
std::pair<double, double> cpp_pmj02_points(uint64_t seed, uint32_t n) {
  py::gil_scoped_release unlocked;
  const auto start = std::chrono::steady_clock::now();
  const sequence::Pmj02 gen(seed);
  std::vector<Point2> out(n);
  for (uint32_t i = 0; i < n; ++i)
    out[i] = gen.at(i);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  double sum = 0.0;
  for (const Point2& p : out)
    sum += p.x + p.y;
  return {seconds, sum};
}

}  // namespace
}  // namespace disklab::python

PYBIND11_MODULE(_disklab, m) {
  using namespace disklab;
  using namespace disklab::python;
  m.doc() = "disklab's compiled core; use the disklab package";

  m.def("sequence_names", &sequence::sequence_names);
  py::class_<PySequence>(m, "Sequence")
      .def(py::init<const std::string&, uint64_t, std::optional<uint32_t>>(), py::arg("name"),
           py::arg("seed"), py::arg("capacity"))
      .def_property_readonly("name", &PySequence::name)
      .def_property_readonly("seed", &PySequence::seed)
      .def("points", &PySequence::points, py::arg("first"), py::arg("count"))
      .def("at", &PySequence::at, py::arg("indices"));

  m.def("strategy_names", &disk::strategy_names);
  py::class_<PyDiskStrategy>(m, "DiskStrategy")
      .def(py::init<const std::string&>(), py::arg("name"))
      .def_property_readonly("name", &PyDiskStrategy::name)
      .def_property_readonly("copies", &PyDiskStrategy::copies)
      .def("sample", &PyDiskStrategy::sample, py::arg("u"))
      .def("weights", &PyDiskStrategy::weights, py::arg("u"))
      .def("invert", &PyDiskStrategy::invert, py::arg("p"))
      .def("pdf", &PyDiskStrategy::pdf, py::arg("p"))
      .def("walk", &PyDiskStrategy::walk, py::arg("sequence"), py::arg("count"), py::arg("first"));

  m.def("map_names", &ellipse::map_names);
  py::class_<PyEllipseMap>(m, "EllipseMap")
      .def(py::init<const std::string&, const Array&, const Array&, double, bool, const Array&,
                    const std::optional<Array>&>(),
           py::arg("kind"), py::arg("center"), py::arg("normal"), py::arg("radius"),
           py::arg("two_sided"), py::arg("o"), py::arg("receiver_normal"))
      .def_property_readonly("valid", [](const PyEllipseMap& s) { return s.map().valid(); })
      .def_property_readonly("solid_angle", [](const PyEllipseMap& s) { return s.map().omega(); })
      .def_property_readonly("kind",
                             [](const PyEllipseMap& s) { return std::string(s.map().name()); })
      .def_property_readonly("copies", [](const PyEllipseMap& s) { return s.map().copies(); })
      .def_property_readonly("has_inverse",
                             [](const PyEllipseMap& s) { return s.map().has_inverse(); })
      .def_property_readonly(
          "is_uniform",
          [](const PyEllipseMap& s) { return ellipse::map_is_uniform(s.map().kind()); })
      .def("sample", &PyEllipseMap::sample, py::arg("u"))
      .def("sample_copies", &PyEllipseMap::sample_copies, py::arg("u"))
      .def("pdf_of", &PyEllipseMap::pdf_of, py::arg("directions"))
      .def("contains", &PyEllipseMap::contains, py::arg("directions"))
      .def("invert", &PyEllipseMap::invert, py::arg("directions"));

  m.def("solid_angle", &solid_angles, py::arg("center"), py::arg("normal"), py::arg("radius"),
        py::arg("two_sided"), py::arg("points"));
  m.def("ellint_f", [](const Array& phi, const Array& mm) {
    return elementwise([](double p, double k) { return math::ellint_f(p, k); }, phi, mm);
  });
  m.def("ellint_pi", [](const Array& n, const Array& phi, const Array& mm) {
    return elementwise([](double a, double p, double k) { return math::ellint_pi(a, p, k); }, n,
                       phi, mm);
  });
  m.def("carlson_rf", [](const Array& x, const Array& y, const Array& z) {
    return elementwise([](double a, double b, double c) { return math::carlson_rf(a, b, c); }, x, y,
                       z);
  });
  m.def("carlson_rd", [](const Array& x, const Array& y, const Array& z) {
    return elementwise([](double a, double b, double c) { return math::carlson_rd(a, b, c); }, x, y,
                       z);
  });
  m.def("carlson_rj", [](const Array& x, const Array& y, const Array& z, const Array& p) {
    return elementwise(
        [](double a, double b, double c, double d) { return math::carlson_rj(a, b, c, d); }, x, y,
        z, p);
  });
  m.def("l2_star", &l2_star, py::arg("points"));

  py::module_ bench = m.def_submodule("_bench", "the C++ loops of bench/python_ratios.py");
  bench.def("sample_loop", &cpp_sample_loop, py::arg("map"), py::arg("u"));
  bench.def("pmj02_points", &cpp_pmj02_points, py::arg("seed"), py::arg("count"));
}
