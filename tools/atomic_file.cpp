// SPDX-License-Identifier: GPL-3.0-or-later
#include "atomic_file.h"

#include "tool_error.h"

#include <filesystem>
#include <system_error>
#include <unistd.h>

namespace ce_tool {

namespace fs = std::filesystem;

Atomic_file::Atomic_file(const std::string& path)
    : path_(path)
{
  const fs::path target(path);
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  tmp_ = (dir / ("." + target.filename().string() + ".tmp" + std::to_string(::getpid()))).string();
  out_.open(tmp_, std::ios::binary | std::ios::trunc);
  if (!out_)
    fail("cannot write '" + path + "': cannot create a file in '" + dir.string() + "'");
}

Atomic_file::~Atomic_file()
{
  if (!committed_) {
    out_.close();
    std::error_code ignored;
    fs::remove(tmp_, ignored);
  }
}

void Atomic_file::flush()
{
  out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  buffer_.clear();
  if (!out_)
    fail("cannot write '" + path_ + "': write error");
}

void Atomic_file::commit()
{
  flush();
  out_.close();
  if (!out_)
    fail("cannot write '" + path_ + "': write error");
  std::error_code ec;
  fs::rename(tmp_, path_, ec);
  if (ec)
    fail("cannot write '" + path_ + "': " + ec.message());
  committed_ = true;
}

} // namespace ce_tool
