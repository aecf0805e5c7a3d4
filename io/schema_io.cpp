#include "io/schema_io.hpp"

#include <fmt/core.h>

#include <cmath>
#include <stdexcept>

#include "physics/checked_cast.hpp"

namespace magnus {

H5Writer::id FileGroups::operator()(const std::string& group) {
  if (group == "/") return w.file();
  auto it = ids.find(group);
  return it != ids.end() ? it->second : (ids[group] = w.group(group));
}

void write_attrs(const std::vector<AttrValue>& values, FileGroups& g, Gaps gaps) {
  for (const AttrValue& a : values) {
    const H5Writer::id obj = g(a.group);
    if (a.kind == AttrKind::text) {
      g.w.attr(obj, a.name, a.text);
    } else if (!a.number || (gaps != Gaps::as_is && !std::isfinite(*a.number))) {  // never NaN in a file: omitted and listed
      g.undefined[a.group].push_back(a.name);
      continue;
    } else if (a.kind == AttrKind::integer) {
      g.w.attr(obj, a.name, checked_cast<long>(*a.number, a.name));
    } else {
      g.w.attr(obj, a.name, *a.number);
    }
    if (*a.units) g.w.attr(obj, (std::string(a.name) + "_units").c_str(), a.units);
  }
}

void write_undefined(FileGroups& g) {
  for (const auto& [group, names] : g.undefined) {
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    g.w.attr(g(group), "undefined", list);
  }
}

void write_column(FileGroups& g, const std::string& group, const char* name, const char* units,
                  const std::string& description, std::vector<double> v, Gaps gaps) {
  size_t defined = 0;
  for (double& x : v) {
    defined += std::isfinite(x) ? 1 : 0;
    if (gaps != Gaps::as_is && !std::isfinite(x)) x = kFillValue;
  }
  if (gaps == Gaps::fill_or_omit && defined == 0 && !v.empty()) {
    g.undefined[group].push_back(name);
    return;
  }
  g.w.dataset(g(group), name, {v.size()}, v.data(), units, description);
  if (gaps != Gaps::as_is && defined < v.size()) g.w.attr(g.w.open(group + "/" + name), "_FillValue", kFillValue);
}

std::vector<double> read_column(const ResultFile& f, const std::string& group, const char* name, size_t n) {
  const std::string path = group + "/" + name;
  if (!f.has(path)) throw std::runtime_error(fmt::format("{}: no dataset {}", f.path(), path));
  std::vector<double> v = f.dataset(path);
  if (v.size() != n)
    throw std::runtime_error(fmt::format("{}: {} has {} values, not {}", f.path(), path, v.size(), n));
  for (double& x : v)
    if (x == kFillValue) x = std::nan("");
  return v;
}

}  // namespace magnus
