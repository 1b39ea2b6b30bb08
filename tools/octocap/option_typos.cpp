#include "option_typos.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace {

size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

}  // namespace

int report_unknown_options(const CLI::App& app, int argc, char** argv) {
  if (argc < 2) return 0;
  const CLI::App* sub = nullptr;
  for (const CLI::App* s : app.get_subcommands([](const CLI::App*) { return true; }))
    if (s->get_name() == argv[1]) sub = s;
  if (sub == nullptr) return 0;  // CLI11 names an unknown subcommand itself
  // A nested command (octocap security add): its own options count.
  std::string command = argv[1];
  int first = 2;
  for (bool deeper = true; deeper && first < argc;) {
    deeper = false;
    for (const CLI::App* s : sub->get_subcommands([](const CLI::App*) { return true; }))
      if (s->get_name() == argv[first]) {
        sub = s;
        command += std::string(" ") + argv[first++];
        deeper = true;
        break;
      }
  }
  std::vector<std::string> known = {"help"};
  for (const CLI::Option* o : sub->get_options())
    for (const std::string& n : o->get_lnames()) known.push_back(n);
  int unknown = 0;
  for (int i = first; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--") break;  // what follows is values only
    if (arg.size() < 3 || arg.compare(0, 2, "--") != 0) continue;
    const std::string name = arg.substr(2, arg.find('=') == std::string::npos ? std::string::npos : arg.find('=') - 2);
    if (std::find(known.begin(), known.end(), name) != known.end()) continue;
    std::string nearest;
    size_t best = std::string::npos;
    for (const std::string& k : known)
      if (const size_t d = edit_distance(name, k); d < best) best = d, nearest = k;
    ++unknown;
    if (best <= std::max<size_t>(2, name.size() / 3))
      std::fprintf(stderr, "octocap %s: unknown option --%s; did you mean --%s?\n", command.c_str(), name.c_str(),
                   nearest.c_str());
    else
      std::fprintf(stderr, "octocap %s: unknown option --%s (octocap %s --help lists them)\n", command.c_str(),
                   name.c_str(), command.c_str());
  }
  return unknown ? 2 : 0;
}
