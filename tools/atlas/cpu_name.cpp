#include "atlas/cpu_name.hpp"

#include <fstream>

namespace edgewise::atlas {
namespace {

// The value of the first "key<spaces>: value" line, or "".
std::string cpuinfo_field(const std::string& key) {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line)) {
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    std::string name = line.substr(0, colon);
    while (!name.empty() && (name.back() == ' ' || name.back() == '\t'))
      name.pop_back();
    if (name != key) continue;
    std::size_t start = colon + 1;
    while (start < line.size() && line[start] == ' ')
      ++start;
    return line.substr(start);
  }
  return "";
}

}  // namespace

std::string cpu_name() {
  std::string name = cpuinfo_field("model name");
  const std::string family = cpuinfo_field("cpu family"), model = cpuinfo_field("model");
  if (name.empty())
    name = cpuinfo_field("CPU part").empty() ? "" : "ARM CPU part " + cpuinfo_field("CPU part");
  if (name.empty()) return "unknown CPU";
  if (!family.empty() && !model.empty()) name += " (family " + family + " model " + model + ")";
  return name;
}

}  // namespace edgewise::atlas
