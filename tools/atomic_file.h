// SPDX-License-Identifier: GPL-3.0-or-later
// Writing an output file all or nothing: an error (a Tool_error) leaves no
// partial file, and an existing file is replaced only by a complete one.
#ifndef CE_TOOLS_ATOMIC_FILE_H
#define CE_TOOLS_ATOMIC_FILE_H

#include <fstream>
#include <string>

namespace ce_tool {

// Text appended to text() goes, a megabyte at a time, to a temporary file beside
// `path`, which commit() renames to `path`; without commit() (an error on the
// way), the temporary file is removed and `path` left as it was.
class Atomic_file
{
public:
  explicit Atomic_file(const std::string& path);
  ~Atomic_file();
  Atomic_file(const Atomic_file&) = delete;
  Atomic_file& operator=(const Atomic_file&) = delete;

  std::string& text() { return buffer_; }
  // Writes the text appended so far if it is a megabyte or more.
  void flush_if_full()
  {
    if (buffer_.size() >= (std::size_t(1) << 20))
      flush();
  }
  void commit();

private:
  void flush();

  std::string path_, tmp_;
  std::ofstream out_;
  std::string buffer_;
  bool committed_ = false;
};

} // namespace ce_tool

#endif // CE_TOOLS_ATOMIC_FILE_H
