// What live mode shows of an error, in the window's overlay and on the terminal alike: the
// line that names the file:line to fix (a shader's before the script's; of Lua lines the last,
// the cause), the offending source line, and the other lines of the message before its
// traceback.
#pragma once
#include <string>
#include <vector>

namespace sn::live {

struct ErrorReport {
  std::string headline;               // "file:line: message" (or the message's first line)
  std::string where;                  // "file:line" of the headline; "" when it names none
  std::string source;                 // "  LINE | text" of that line; "" when it cannot be read
  std::vector<std::string> context;   // the message's other lines, traceback left out
  std::string traceback;              // "stack traceback:\n..." or ""
};

ErrorReport report_error(const std::string& message);

// The report as the terminal and the overlay print it: headline, source, context (at most
// `max_context` lines of it), one per line.
std::vector<std::string> report_lines(const ErrorReport& r, size_t max_context = 4);

}  // namespace sn::live
