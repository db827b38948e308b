// SPDX-License-Identifier: GPL-3.0-or-later
#include "atomic_file.h"

#include "tool_error.h"

#include <filesystem>
#include <fstream>
#include <system_error>
#include <unistd.h>

namespace ce_tool {

namespace fs = std::filesystem;

void write_file_atomically(const std::string& path, const std::string& text)
{
  const fs::path target(path);
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  const fs::path tmp = dir / ("." + target.filename().string() + ".tmp" + std::to_string(::getpid()));
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out)
      fail("cannot write '" + path + "': cannot create a file in '" + dir.string() + "'");
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.close();
    if (!out) {
      std::error_code ec;
      fs::remove(tmp, ec);
      fail("cannot write '" + path + "': write error");
    }
  }
  std::error_code ec;
  fs::rename(tmp, target, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    fail("cannot write '" + path + "': " + ec.message());
  }
}

} // namespace ce_tool
