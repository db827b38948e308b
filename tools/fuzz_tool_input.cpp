// libFuzzer target for the input path of the `curvature` tool: the bytes are a
// mesh file (the first byte picks the extension: .off .ply .obj .stl); the tool's
// reader, validation, soup repair and the paraboloid fit run on it. A Tool_error
// is the expected outcome for bad input; anything else (crash, sanitizer report,
// other exception, hang) is a finding.
//   cmake -DCMAKE_CXX_COMPILER=clang++ -DCE_BUILD_FUZZERS=ON ... && ./fuzz_tool_input -runs=N
#define CE_CURVATURE_NO_MAIN
#include "curvature.cpp"

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if (size < 1 || size > 1 << 16)
    return 0;
  static const char* const extensions[] = {".off", ".ply", ".obj", ".stl"};
  const std::string path = "/tmp/ce_fuzz_tool_input_" + std::to_string(::getpid()) + extensions[data[0] % 4];
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  try {
    Options o;
    o.input = path;
    o.threads = 1;
    const Soup soup = read_input(path);
    std::vector<V> file_to_mesh;
    Silence_cerr silence;  // repair notes
    const Mesh mesh = build_mesh(soup, file_to_mesh);
    double seconds = 0;
    const std::vector<Row> rows = estimate(o, mesh, file_to_mesh, seconds);
    if (rows.size() != soup.points.size())
      __builtin_trap();
    for (const Row& r : rows)
      if (r.status == CE::Estimation_status::not_estimable && !std::isnan(r.mean))
        __builtin_trap();
  } catch (const Tool_error&) {
  }
  std::remove(path.c_str());
  return 0;
}
