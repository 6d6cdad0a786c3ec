#pragma once
// Reading the committed reference tables (reference/*.csv), shared by the property tests and
// `disklab accuracy`. Format: '#' lines record provenance, the first other line names the
// columns, every row has one field per column. A missing or malformed table throws (a test
// failure or an exit 1, never a silent skip). Header-only, no dependency beyond the standard
// library, so the generators, tests and CLI read the files the same way.
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace disklab::reference {

struct CsvTable {
  std::filesystem::path path;
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;  // fields as text: values keep all 45 digits

  // Field i of row r as a double (strtod rounds correctly); throws on a non-number.
  double number(std::size_t r, std::size_t i) const {
    const std::string& text = rows[r][i];
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end == text.c_str())
      throw std::runtime_error(path.string() + ": row " + std::to_string(r + 1) + ", column '" +
                               columns[i] + "': not a number '" + text + "'");
    return v;
  }
};

inline std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream s(line);
  std::string field;
  while (std::getline(s, field, ','))
    fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

// Reads `path`. `expected_columns`, when given, must equal the header's leading columns (a
// table regenerated with other columns must not be read by position silently).
inline CsvTable read_csv_table(const std::filesystem::path& path,
                               const std::vector<std::string>& expected_columns = {},
                               std::size_t min_rows = 1) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("reference table missing: " + path.string());
  CsvTable table;
  table.path = path;
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    if (table.columns.empty()) {
      table.columns = split_csv_line(line);
      for (std::size_t i = 0; i < expected_columns.size(); ++i)
        if (i >= table.columns.size() || table.columns[i] != expected_columns[i])
          throw std::runtime_error("unexpected header in " + path.string() + ": " + line);
      continue;
    }
    auto fields = split_csv_line(line);
    if (fields.size() != table.columns.size())
      throw std::runtime_error("malformed row in " + path.string() + ": " + line);
    table.rows.push_back(std::move(fields));
  }
  if (table.rows.size() < min_rows)
    throw std::runtime_error("reference table too short (" + std::to_string(table.rows.size()) +
                             " rows): " + path.string());
  return table;
}

// Signed distance in representable doubles between a and b (0 if equal; both finite).
inline int64_t ulp_distance(double a, double b) {
  auto key = [](double x) {
    int64_t i;
    std::memcpy(&i, &x, sizeof i);
    return i < 0 ? std::numeric_limits<int64_t>::min() - i : i;  // monotone in x
  };
  return key(a) - key(b);
}

// One row of elliptic_f.csv (phi, m, F), elliptic_pi.csv (n, phi, m, Pi) or a table of the same
// shape: the inputs, and the 45-digit value as text (parse it at any precision) and rounded.
struct EllipticRow {
  std::vector<double> inputs;
  std::string value;
  double value_rounded = 0.0;  // correctly rounded to double (strtod rounds correctly)
};

// Reads an elliptic-integral table with `input_count` inputs per row (the one reader of these
// tables for the tests and `disklab accuracy`); `columns`, when given, must be its header.
inline std::vector<EllipticRow> read_elliptic_table(const std::filesystem::path& path,
                                                    std::size_t input_count,
                                                    const std::vector<std::string>& columns = {},
                                                    std::size_t min_rows = 1) {
  const CsvTable table = read_csv_table(path, columns, min_rows);
  if (table.columns.size() != input_count + 1)
    throw std::runtime_error(path.string() + ": expected " + std::to_string(input_count + 1) +
                             " columns");
  std::vector<EllipticRow> rows;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    EllipticRow row;
    for (std::size_t i = 0; i < input_count; ++i)
      row.inputs.push_back(table.number(r, i));
    row.value = table.rows[r][input_count];
    row.value_rounded = table.number(r, input_count);
    rows.push_back(std::move(row));
  }
  return rows;
}

// The scene columns solid_angle.csv and projected_P.csv share, in the same positions: id,
// category, cx..cz, nx..nz, radius, ox..oz (columns 0-11).
struct DiskSceneColumns {
  int id = 0;
  std::string category;
  double center[3] = {}, normal[3] = {}, point[3] = {};
  double radius = 0.0;
};
inline void read_disk_scene(const CsvTable& t, std::size_t r, DiskSceneColumns& row) {
  row.id = static_cast<int>(t.number(r, 0));
  row.category = t.rows[r][1];
  for (std::size_t k = 0; k < 3; ++k) {
    row.center[k] = t.number(r, 2 + k);
    row.normal[k] = t.number(r, 5 + k);
    row.point[k] = t.number(r, 9 + k);
  }
  row.radius = t.number(r, 8);
}

// One row of solid_angle.csv: a disk, a shading point and the 45-digit solid angle.
struct SolidAngleRow : DiskSceneColumns {
  bool two_sided = false;
  double distance = 0.0;   // |o - c| / r
  std::string omega_text;  // the reference, all digits
  double omega = 0.0;      // the same rounded to double
};

// Reads solid_angle.csv (the one reader of that table for the tests and `disklab accuracy`).
inline std::vector<SolidAngleRow> read_solid_angle_table(const std::filesystem::path& path) {
  const CsvTable t =
      read_csv_table(path, {"id", "category", "cx", "cy", "cz", "nx", "ny", "nz", "radius", "ox",
                            "oy", "oz", "two_sided", "distance", "omega"});
  std::vector<SolidAngleRow> rows;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const auto num = [&](std::size_t i) { return t.number(r, i); };
    SolidAngleRow row;
    read_disk_scene(t, r, row);
    row.two_sided = t.rows[r][12] == "1";
    row.distance = num(13);
    row.omega_text = t.rows[r][14];
    row.omega = num(14);
    rows.push_back(row);
  }
  return rows;
}

// One row of projected_P.csv: a disk, a shading point, its receiver normal and the 45-digit
// projected solid angle P with its quadrature's relative error estimate.
struct ProjectedRow : DiskSceneColumns {
  double receiver_normal[3] = {};
  bool two_sided = false;
  double distance = 0.0;    // |o - c| / r
  bool straddles = false;   // the receiver's horizon plane cuts the disk
  std::string p_text;       // the reference, all digits
  double p = 0.0;           // the same rounded to double
  double quad_error = 0.0;  // relative error estimate of the reference
};

// Reads projected_P.csv (the one reader of that table for the tests and `disklab accuracy`).
inline std::vector<ProjectedRow> read_projected_table(const std::filesystem::path& path) {
  const CsvTable t =
      read_csv_table(path, {"id", "category",  "cx",       "cy",        "cz", "nx",        "ny",
                            "nz", "radius",    "ox",       "oy",        "oz", "rx",        "ry",
                            "rz", "two_sided", "distance", "straddles", "P",  "quad_error"});
  std::vector<ProjectedRow> rows;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const auto num = [&](std::size_t i) { return t.number(r, i); };
    ProjectedRow row;
    read_disk_scene(t, r, row);
    for (std::size_t k = 0; k < 3; ++k)
      row.receiver_normal[k] = num(12 + k);
    row.two_sided = t.rows[r][15] == "1";
    row.distance = num(16);
    row.straddles = t.rows[r][17] == "1";
    row.p_text = t.rows[r][18];
    row.p = num(18);
    row.quad_error = num(19);
    rows.push_back(row);
  }
  return rows;
}

}  // namespace disklab::reference
