#include "live/error_report.h"

#include <regex>
#include <sstream>

#include "io/read_file.h"

namespace sn::live {

namespace {

bool is_lua(const std::string& file) { return file.size() >= 4 && file.compare(file.size() - 4, 4, ".lua") == 0; }

// Line `n` (from 1) of `file`, or "" when the file or the line cannot be read.
std::string source_line(const std::string& file, int n) {
  std::string text;
  try {
    text = io::read_file(file, "source", 64u << 20);
  } catch (const std::exception&) {
    return "";
  }
  std::istringstream in(text);
  std::string line;
  for (int i = 1; std::getline(in, line); ++i)
    if (i == n) return line;
  return "";
}

std::string trim(const std::string& s) {
  size_t a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

}  // namespace

ErrorReport report_error(const std::string& message) {
  ErrorReport r;
  std::string body = message;
  if (size_t tb = body.find("\nstack traceback:"); tb != std::string::npos)
    r.traceback = body.substr(tb + 1), body.resize(tb);
  std::vector<std::string> lines;
  std::istringstream in(body);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  if (lines.empty()) lines.push_back("(no message)");

  // The headline: the first line naming a shader's file:line, else the last naming any file:line
  // (an error inside a module the script loads names the script first and the cause last).
  // A GLSL given as a string is located "script.lua:2 (glsl of NAME):LINE:" (the headline was
  // cut to "NAME):LINE:", spaces and all): one location.
  static const std::regex where(R"(((?:[^\s:]+:\d+ \([^)]*\))|[^\s:]+):(\d+):)");
  int pick = -1, last = -1;
  std::smatch m;
  for (int i = 0; i < int(lines.size()); ++i) {
    if (!std::regex_search(lines[size_t(i)], m, where)) continue;
    last = i;
    if (!is_lua(m[1])) {
      pick = i;
      break;
    }
  }
  if (pick < 0) pick = last;
  int line_no = 0;
  std::string file;
  if (pick >= 0) {
    std::regex_search(lines[size_t(pick)], m, where);
    file = m[1], line_no = std::stoi(m[2]);
    r.where = file + ":" + std::string(m[2]);
    // "error loading module ... from file '...':" is context; the headline starts at the file:line.
    r.headline = trim(lines[size_t(pick)].substr(size_t(m.position(0))));
  } else {
    pick = 0;
    r.headline = trim(lines[0]);
  }
  // A GLSL log already prints the offending line, indented, under its file:line.
  int skip = -1;
  if (pick + 1 < int(lines.size()) && !lines[size_t(pick) + 1].empty() && lines[size_t(pick) + 1][0] == ' ' &&
      !std::regex_search(lines[size_t(pick) + 1], where))
    skip = pick + 1;
  std::string text = skip >= 0 ? lines[size_t(skip)] : line_no > 0 ? source_line(file, line_no) : "";
  if (!trim(text).empty()) r.source = "  " + std::to_string(line_no) + " | " + trim(text);
  for (int i = 0; i < int(lines.size()); ++i)
    if (i != pick && i != skip && !trim(lines[size_t(i)]).empty()) r.context.push_back(trim(lines[size_t(i)]));
  return r;
}

std::vector<std::string> report_lines(const ErrorReport& r, size_t max_context) {
  std::vector<std::string> out{r.headline};
  if (!r.source.empty()) out.push_back(r.source);
  for (size_t i = 0; i < r.context.size() && i < max_context; ++i) out.push_back(r.context[i]);
  if (r.context.size() > max_context) out.push_back("(" + std::to_string(r.context.size() - max_context) + " more lines on the terminal)");
  return out;
}

}  // namespace sn::live
