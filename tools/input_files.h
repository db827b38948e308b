// SPDX-License-Identifier: GPL-3.0-or-later
// The tool's access to its input files: formats are told by extension, and a
// file is checked to be a readable regular file before any reader sees it.
#ifndef CE_TOOLS_INPUT_FILES_H
#define CE_TOOLS_INPUT_FILES_H

#include "mesh_readers.h"
#include "tool_error.h"

#include <cstdint>
#include <string>

namespace ce_tool {

// The extension of `path` in lower case, with its dot (".off"), or "".
std::string lower_extension(const std::string& path);

// The size of a readable regular file.
std::uintmax_t check_readable(const std::string& path);

// The whole content of a readable regular file.
std::string read_text_file(const std::string& path);

// Runs one of the strict readers of mesh_readers.h on the file's text.
template <typename Reader>
auto read_strictly(const std::string& path, Reader reader)
{
  const std::string text = read_text_file(path);
  try {
    return reader(text);
  } catch (const Read_error& e) {
    fail("malformed file '" + path + "': " + e.what());
  }
}

} // namespace ce_tool

#endif // CE_TOOLS_INPUT_FILES_H
