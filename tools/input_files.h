// SPDX-License-Identifier: GPL-3.0-or-later
// The tool's access to its input files: formats are told by extension, and a
// file is checked to be a readable regular file before any reader sees it.
#ifndef CE_TOOLS_INPUT_FILES_H
#define CE_TOOLS_INPUT_FILES_H

#include "mesh_readers.h"
#include "tool_error.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

namespace ce_tool {

// The extension of `path` in lower case, with its dot (".off"), or "".
std::string lower_extension(const std::string& path);

// The size of a readable regular file.
std::uintmax_t check_readable(const std::string& path);

// The whole content of a file, in a buffer that is not zeroed first (a
// std::string of the file's size would be: 82 MB written twice for the OFF of a
// 1M-vertex mesh).
class File_text
{
public:
  explicit File_text(std::size_t size)
      : data_(new char[size])
      , size_(size)
  {}
  char* data() { return data_.get(); }
  std::string_view view() const { return std::string_view(data_.get(), size_); }

private:
  std::unique_ptr<char[]> data_;
  std::size_t size_;
};

// The whole content of a readable regular file.
File_text read_text_file(const std::string& path);

// Runs one of the strict readers of mesh_readers.h on the file's text.
template <typename Reader>
auto read_strictly(const std::string& path, Reader reader)
{
  const File_text text = read_text_file(path);
  try {
    return reader(text.view());
  } catch (const Read_error& e) {
    fail("malformed file '" + path + "': " + e.what());
  }
}

} // namespace ce_tool

#endif // CE_TOOLS_INPUT_FILES_H
