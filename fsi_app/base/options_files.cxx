// SPDX-License-Identifier: BSD-2-Clause
#include "options_files.h"
#include <fstream>
#include <sstream>
#include <sys/stat.h>

namespace fsi {

/* Options whose value is a file the run reads. */
static bool NamesInputFile(const std::string &option)
{
  const std::string outlet = "_pressure_waveform"; /* -outlets_<group>_pressure_waveform */
  return option == "-options_file" || option == "-mesh" || option == "-restart" || option == "-fluid_inlet_pressure_waveform" || option == "-fluid_inflow_waveform" || option == "-structure_centerline" ||
         (option.rfind("-outlets_", 0) == 0 && option.size() > outlet.size() && option.compare(option.size() - outlet.size(), outlet.size(), outlet) == 0);
}

static bool IsFile(const std::string &path)
{
  struct stat st;
  return stat(path.c_str(), &st) == 0 && !S_ISDIR(st.st_mode);
}

/* a/b/../c -> a/c, ./a -> a */
static std::string Tidy(const std::string &path)
{
  std::vector<std::string> parts;
  std::istringstream       in(path);
  for (std::string p; std::getline(in, p, '/');) {
    if (p == "." || (p.empty() && !parts.empty())) continue;
    if (p == ".." && !parts.empty() && parts.back() != ".." && !parts.back().empty()) parts.pop_back();
    else parts.push_back(p);
  }
  std::string out;
  for (size_t k = 0; k < parts.size(); k++) out += (k ? "/" : "") + parts[k];
  return out.empty() ? "." : out;
}

/* `path` as named in the file `from` ("": the command line): relative to from's folder when
   the file is there, else as given (the working directory). */
static std::string Resolve(const std::string &path, const std::string &from)
{
  if (from.empty() || path.empty() || path[0] == '/') return path;
  const size_t slash = from.rfind('/');
  if (slash == std::string::npos) return path;
  const std::string near = Tidy(from.substr(0, slash + 1) + path);
  return IsFile(near) ? near : path;
}

/* The identity of a file (device and inode): one file under two names is one file. */
static std::string Identity(const std::string &path)
{
  struct stat st;
  return stat(path.c_str(), &st) == 0 ? std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino) : path;
}

static std::string Expand(const std::vector<std::string> &in, const std::string &from, std::vector<std::string> &chain, std::vector<std::string> &out)
{
  for (size_t i = 0; i < in.size(); i++) {
    const std::string &a = in[i];
    if (!NamesInputFile(a) || i + 1 == in.size() || in[i + 1].empty() || in[i + 1][0] == '-') {
      out.push_back(a);
      continue;
    }
    const std::string path = Resolve(in[++i], from);
    if (a != "-options_file") {
      out.insert(out.end(), {a, path});
      continue;
    }
    std::string cycle;
    for (const std::string &c : chain) cycle += (cycle.empty() ? "" : " includes ") + c;
    for (const std::string &c : chain)
      if (Identity(c) == Identity(path)) return "-options_file: " + cycle + " includes " + path + " again: options files cannot include themselves, directly or through others";
    if (!IsFile(path)) return "-options_file " + path + (from.empty() ? "" : " (named in " + from + ")") + ": no such file";
    std::ifstream file(path);
    if (!file) return "-options_file " + path + ": cannot be read";
    std::vector<std::string> tokens;
    for (std::string line; std::getline(file, line);) {
      std::istringstream words(line.substr(0, line.find('#')));
      for (std::string w; words >> w;) tokens.push_back(w);
    }
    chain.push_back(path);
    const std::string error = Expand(tokens, path, chain, out);
    if (!error.empty()) return error;
    chain.pop_back();
  }
  return "";
}

std::string ExpandOptionsFiles(std::vector<std::string> &args)
{
  std::vector<std::string> chain, out;
  const std::string        error = Expand(args, "", chain, out);
  if (error.empty()) args = out;
  return error;
}

} // namespace fsi
