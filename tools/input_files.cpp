// SPDX-License-Identifier: GPL-3.0-or-later
#include "input_files.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace ce_tool {

namespace fs = std::filesystem;

std::string lower_extension(const std::string& path)
{
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

std::uintmax_t check_readable(const std::string& path)
{
  std::error_code ec;
  if (!fs::exists(path, ec))
    fail("cannot read '" + path + "': no such file");
  if (!fs::is_regular_file(path, ec))
    fail("cannot read '" + path + "': not a regular file");
  const std::uintmax_t bytes = fs::file_size(path, ec);
  std::ifstream probe(path, std::ios::binary);
  if (ec || !probe)
    fail("cannot read '" + path + "': cannot open the file");
  return bytes;
}

File_text read_text_file(const std::string& path)
{
  const std::uintmax_t bytes = check_readable(path);
  std::ifstream in(path, std::ios::binary);
  File_text text(static_cast<std::size_t>(bytes));
  in.read(text.data(), static_cast<std::streamsize>(bytes));
  if (in.bad() || static_cast<std::uintmax_t>(in.gcount()) != bytes)
    fail("cannot read '" + path + "': read error");
  return text;
}

} // namespace ce_tool
