// SPDX-License-Identifier: GPL-3.0-or-later
// The tool's errors: every error a user can cause is thrown as a Tool_error and
// ends in main as one line on stderr and the error's exit code.
#ifndef CE_TOOLS_TOOL_ERROR_H
#define CE_TOOLS_TOOL_ERROR_H

#include <stdexcept>
#include <string>

namespace ce_tool {

struct Tool_error : std::runtime_error
{
  int code;
  Tool_error(const std::string& message, int code = 1)
      : std::runtime_error(message)
      , code(code)
  {}
};

[[noreturn]] inline void fail(const std::string& message, int code = 1) { throw Tool_error(message, code); }

// One line: messages from libraries may hold newlines.
inline std::string one_line(std::string s)
{
  for (char& c : s)
    if (c == '\n' || c == '\r')
      c = ' ';
  return s;
}

} // namespace ce_tool

#endif // CE_TOOLS_TOOL_ERROR_H
