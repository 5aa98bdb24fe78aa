// The libFuzzer target for the genmesh program's argument and crease parsing:
// the whole CLI (tools/genmesh.cpp, its main renamed) runs in-process on a
// command line and crease file made from the input (see
// genmesh_fuzz::parse_cli_case). Exit codes other than 0-3 abort (a finding);
// so do crashes, sanitizer reports and hangs (libFuzzer's -timeout).
#define main genmesh_cli_main
#include "../tools/genmesh.cpp"
#undef main

#include "genmesh_fuzz.h"

#include <cstdlib>
#include <fcntl.h>
#include <unistd.h>
#include <filesystem>
#include <fstream>

namespace {

genmesh_fuzz::Cli_paths fuzz_paths;
std::string scratch_dir;   // the program runs here: fuzzed output names land in it

void write_text(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  const auto dir = std::filesystem::temp_directory_path() / ("genmesh_fuzz_cli." + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  fuzz_paths = {(dir / "in.off").string(),      (dir / "bad.off").string(), (dir / "rep.off").string(),
                (dir / "creases.txt").string(), (dir / "out").string(),     (dir / "tri.off").string()};
  genmesh_fuzz::write_cli_meshes(fuzz_paths);
  static const std::filesystem::path made = dir;
  std::atexit([] { std::filesystem::remove_all(made); });
  scratch_dir = dir.string();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 1 << 16) return 0;
  genmesh_fuzz::Cli_case c =
      genmesh_fuzz::parse_cli_case(std::string_view(reinterpret_cast<const char*>(data), size), fuzz_paths);
  if (!c.runnable) return 0;
  write_text(fuzz_paths.creases, c.creases);
  std::vector<std::string> args{"genmesh"};
  args.insert(args.end(), c.args.begin(), c.args.end());
  // Last, so that they win: keep subdivision small and fast.
  args.insert(args.end(), {"--max-memory", "64M"});
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const int home = open(".", O_RDONLY | O_DIRECTORY);
  if (home < 0 || chdir(scratch_dir.c_str()) != 0) std::abort();
  const int rc = genmesh_cli_main(static_cast<int>(args.size()), argv.data());
  if (fchdir(home) != 0) std::abort();
  close(home);
  if (rc < 0 || rc > 3) std::abort();
  return 0;
}
