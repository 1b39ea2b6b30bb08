#include "io/calibration_toml.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <toml++/toml.h>

#include "core/error.h"

namespace octocap::internal {
namespace {

struct TableRef {
  std::string key;
  const toml::table* table;
  uint32_t line;
};

[[noreturn]] void fail(const std::string& path, const std::string& where, const std::string& what) {
  throw Error(Errc::parse, path + ": [" + where + "]: " + what);
}

std::vector<double> numbers(const toml::table& t, const char* key, const std::string& path,
                            const std::string& where) {
  const toml::array* arr = t[key].as_array();
  if (!arr) fail(path, where, std::string("missing or non-array '") + key + "'");
  std::vector<double> out;
  for (const toml::node& n : *arr) {
    if (n.is_array()) {
      for (const toml::node& m : *n.as_array()) {
        auto v = m.value<double>();
        if (!v) fail(path, where, std::string("'") + key + "' holds a non-number");
        out.push_back(*v);
      }
    } else {
      auto v = n.value<double>();
      if (!v) fail(path, where, std::string("'") + key + "' holds a non-number");
      out.push_back(*v);
    }
  }
  for (double v : out)
    if (!std::isfinite(v)) fail(path, where, std::string("'") + key + "' holds a NaN or infinite value");
  return out;
}

void expect_count(const std::vector<double>& v, size_t n, const char* key, const std::string& path,
                  const std::string& where) {
  if (v.size() != n)
    fail(path, where, std::string("'") + key + "' must have " + std::to_string(n) + " numbers, has " +
                          std::to_string(v.size()));
}

Camera read_camera(const TableRef& ref, const std::string& path) {
  const toml::table& t = *ref.table;
  CameraValues v;
  const auto size = numbers(t, "size", path, ref.key);
  expect_count(size, 2, "size", path, ref.key);
  v.width = size[0], v.height = size[1];
  const auto m = numbers(t, "matrix", path, ref.key);
  expect_count(m, 9, "matrix", path, ref.key);
  for (int i = 0; i < 9; ++i) v.matrix(i / 3, i % 3) = m[i];
  const auto d = numbers(t, "distortions", path, ref.key);
  if (d.size() < 4 || d.size() > 5)
    fail(path, ref.key, "'distortions' must have 4 or 5 numbers, has " + std::to_string(d.size()));
  std::copy(d.begin(), d.end(), v.distortion.begin());
  const auto r = numbers(t, "rotation", path, ref.key);
  expect_count(r, 3, "rotation", path, ref.key);
  v.rotation = {r[0], r[1], r[2]};
  const auto tr = numbers(t, "translation", path, ref.key);
  expect_count(tr, 3, "translation", path, ref.key);
  v.translation = {tr[0], tr[1], tr[2]};
  if (const std::string why = implausible_camera(v); !why.empty()) fail(path, ref.key, why);
  v.name = t["name"].value_or(ref.key);
  v.fisheye = t["fisheye"].value_or(false);
  return camera_of(v);
}

// A TOML basic string: quotes, backslashes and control characters escaped, so any name reads back as written.
std::string toml_string(const std::string& s) {
  std::string out = "\"";
  for (unsigned char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c < 0x20 || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out + "\"";
}

std::string fmt(double v) {
  std::ostringstream s;
  s << std::setprecision(17) << v;
  std::string str = s.str();
  if (str.find_first_of(".eEn") == std::string::npos) str += ".0";
  return str;
}

}  // namespace

Calibration read_calibration_toml(const std::string& path) {
  std::ifstream probe(path);
  if (!probe) throw Error(Errc::io, path + ": cannot open calibration file");
  toml::table root;
  try {
    root = toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    const auto& b = e.source().begin;
    throw Error(Errc::parse, path + ":" + std::to_string(b.line) + ":" + std::to_string(b.column) +
                                 ": malformed TOML: " + std::string(e.description()));
  }
  // toml++ keeps tables sorted by key; the cameras' order is the file's, so sort by source line.
  std::vector<TableRef> cams;
  for (const auto& [key, node] : root) {
    const toml::table* t = node.as_table();
    if (!t || !t->contains("matrix")) continue;  // [metadata] and other non-camera tables
    cams.push_back({std::string(key.str()), t, node.source().begin.line});
  }
  std::stable_sort(cams.begin(), cams.end(), [](const TableRef& a, const TableRef& b) { return a.line < b.line; });
  if (cams.empty()) throw Error(Errc::parse, path + ": no camera table (a table with 'matrix') found");
  Calibration calib;
  for (const auto& ref : cams) calib.push_back(read_camera(ref, path));
  return calib;
}

void write_calibration_toml(const Calibration& calib, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw Error(Errc::io, path + ": cannot open for writing");
  for (size_t i = 0; i < calib.size(); ++i) {
    const Camera& c = calib[i];
    const Eigen::Vector3d r = matrix_to_rodrigues(c.R);
    out << "[cam_" << (i + 1) << "]\n";
    out << "name = " << toml_string(c.name) << "\n";
    out << "size = [ " << fmt(c.width) << ", " << fmt(c.height) << "]\n";
    out << "matrix = [";
    for (int row = 0; row < 3; ++row)
      out << (row ? ", " : " ") << "[ " << fmt(c.K(row, 0)) << ", " << fmt(c.K(row, 1)) << ", " << fmt(c.K(row, 2))
          << "]";
    out << "]\n";
    const size_t nd = c.fisheye ? 4 : 5;
    out << "distortions = [";
    for (size_t k = 0; k < nd; ++k) out << (k ? ", " : " ") << fmt(c.dist[k]);
    out << "]\n";
    out << "rotation = [ " << fmt(r.x()) << ", " << fmt(r.y()) << ", " << fmt(r.z()) << "]\n";
    out << "translation = [ " << fmt(c.t.x()) << ", " << fmt(c.t.y()) << ", " << fmt(c.t.z()) << "]\n";
    out << "fisheye = " << (c.fisheye ? "true" : "false") << "\n\n";
  }
  out << "[metadata]\nadjusted = false\nerror = 0.0\n";
  if (!out) throw Error(Errc::io, path + ": write failed");
}

}  // namespace octocap::internal
