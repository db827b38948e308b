// SPDX-License-Identifier: GPL-3.0-or-later
// Writing an output file all or nothing: an error (a Tool_error) leaves no
// partial file, and an existing file is replaced only by a complete one.
#ifndef CE_TOOLS_ATOMIC_FILE_H
#define CE_TOOLS_ATOMIC_FILE_H

#include <string>

namespace ce_tool {

// Writes to a temporary name beside `path` and renames on success only.
void write_file_atomically(const std::string& path, const std::string& text);

} // namespace ce_tool

#endif // CE_TOOLS_ATOMIC_FILE_H
