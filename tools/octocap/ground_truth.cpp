#include "ground_truth.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream s(line);
  while (std::getline(s, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

}  // namespace

GroundTruth read_ground_truth_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open ground-truth CSV");
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(path + ": empty file");
  const auto header = split(line);
  GroundTruth gt;
  // frame[,time],NAME_x,NAME_y,NAME_z,... (octocap's CSV, with its time column since 1.6)
  const size_t first = header.size() > 1 && header[1] == "time" ? 2 : 1;
  for (size_t i = first; i + 2 < header.size(); i += 3) {
    const std::string& h = header[i];
    if (h.size() < 3 || h.compare(h.size() - 2, 2, "_x") != 0)
      throw std::runtime_error(path + ": header column '" + h + "' is not NAME_x");
    gt.names.push_back(h.substr(0, h.size() - 2));
  }
  size_t lineno = 1;
  while (std::getline(in, line)) {
    ++lineno;
    if (line.empty()) continue;
    const auto cells = split(line);
    std::vector<std::array<double, 3>> frame(gt.names.size(), {NAN, NAN, NAN});
    for (size_t k = 0; k < gt.names.size(); ++k)
      for (int c = 0; c < 3; ++c) {
        const size_t idx = first + 3 * k + c;
        if (idx < cells.size() && !cells[idx].empty()) {
          try {
            frame[k][c] = std::stod(cells[idx]);
          } catch (const std::exception&) {
            throw std::runtime_error(path + ":" + std::to_string(lineno) + ": non-numeric cell '" + cells[idx] + "'");
          }
        }
      }
    gt.frames.push_back(std::move(frame));
  }
  return gt;
}
