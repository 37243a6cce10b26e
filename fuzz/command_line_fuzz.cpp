// Fuzzes raytrace's command line: the tool's own main (compiled in under
// another name), run in a fresh scratch folder that holds two small scenes,
// at its top and again under scenes/, with the arguments taken from the
// input, split at NUL and newline bytes. Whatever the arguments, the tool
// must return, never crash, leak or hit undefined behaviour, and every
// image it leaves in the folder must read back at the scenes' size.
//
// The harness keeps the tool inside the folder: arguments with a '/' or
// equal to ".." are dropped. --report is left out: it times dozens of
// configurations and runs the stability suite, seconds per input.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "meshtrace/io/image.h"

int raytraceMain(int argc, char** argv);

namespace {

namespace fs = std::filesystem;

// fuzz.sh runs this harness with -close_fd_mask=3, which sends the tool's
// output, stderr too, to /dev/null; the harness says why it stopped on a
// copy of stderr taken before that (LLVMFuzzerInitialize runs first).
FILE* harnessLog = stderr;

const fs::path& scratch() {
  static const fs::path dir =
      fs::temp_directory_path() / ("meshtrace-fuzz-cli-" + std::to_string(getpid()));
  return dir;
}

void write(const fs::path& file, std::string_view text) {
  std::ofstream(file, std::ios::binary) << text;
}

constexpr int kWidth = 8, kHeight = 6;

// shapes.sce (every kind of object, mirrors, two lights) and meshes.sce (the
// small meshes of fuzz/meshes) in `dir`, 8x6 pixels.
void makeScenes(const fs::path& dir) {
  fs::create_directories(dir);
  write(dir / "shapes.sce",
        "camera 0 1 6  0 0 0  0 1 0  45 8 6\ndepth 2\nambience 0.2 0.2 0.2\n"
        "light 4 6 4  0.8 0.8 0.8\nlight -3 2 5  0.3 0.3 0.4\n"
        "sphere -1 0.5 0  0.5  0.2 0.2 0.2  0.6 0.3 0.3  0.5 0.5 0.5  30 0.4\n"
        "plane 0 0 0  0 1 0  0.1 0.1 0.1  0.5 0.5 0.5  0 0 0  1 0.3\n"
        "cylinder 1 0.5 0  0.3  0 1 0  1  0.2 0.2 0.2  0.3 0.6 0.3  0.2 0.2 0.2  10 0\n");
  std::string meshes = "camera 2 2 4  0.5 0.5 0.5  0 1 0  50 8 6\nlight 3 5 4  1 1 1\n";
  for (const auto& e : fs::directory_iterator(MESHTRACE_FUZZ_MESHES)) {
    if (e.path().extension() != ".off") continue;
    // Copied through streams, whose reads and writes are retried when a
    // signal interrupts them: libFuzzer's timeout alarm goes off every few
    // seconds, and fs::copy_file gives up on the first interrupted call.
    // A failure here is the harness's, not the tool's: say what it was.
    std::ifstream in(e.path(), std::ios::binary);
    std::ofstream out(dir / e.path().filename(), std::ios::binary);
    out << in.rdbuf();
    out.close();
    if (!in || !out) {
      std::fprintf(harnessLog, "harness: cannot copy %s into %s\n", e.path().c_str(), dir.c_str());
      std::abort();
    }
    meshes += "mesh " + e.path().filename().string() +
              " PHONG  0.2 0.2 0.2  0.6 0.5 0.4  0.3 0.3 0.3  20 0.2\n";
  }
  write(dir / "meshes.sce", meshes);
}

bool isImage(const fs::path& file) {
  const fs::path ext = file.extension();
  return ext == ".png" || ext == ".bmp" || ext == ".ppm" || ext == ".jpg" || ext == ".jpeg";
}

std::vector<std::string> arguments(std::string_view input) {
  std::vector<std::string> args = {"raytrace"};
  std::size_t begin = 0;
  while (begin <= input.size() && args.size() < 16) {
    std::size_t end = input.find_first_of(std::string_view("\0\n", 2), begin);
    if (end == std::string_view::npos) end = input.size();
    const std::string_view arg = input.substr(begin, end - begin);
    const bool outside = arg.find('/') != std::string_view::npos || arg == "..";
    const bool report = arg == "--report" || arg.starts_with("--report=");
    if (!outside && !report) args.emplace_back(arg);
    begin = end + 1;
  }
  return args;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  const int copy = dup(STDERR_FILENO);
  if (copy >= 0) {
    if (FILE* log = fdopen(copy, "w")) {
      // Unbuffered, as stderr is: the message must be out before abort().
      std::setvbuf(log, nullptr, _IONBF, 0);
      harnessLog = log;
    }
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fs::remove_all(scratch());
  makeScenes(scratch());
  makeScenes(scratch() / "scenes");
  std::vector<std::string> args =
      arguments(std::string_view(reinterpret_cast<const char*>(data), size));
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const fs::path before = fs::current_path();
  fs::current_path(scratch());
  raytraceMain(static_cast<int>(args.size()), argv.data());
  for (const auto& e : fs::recursive_directory_iterator(scratch())) {
    if (!e.is_regular_file() || !isImage(e.path())) continue;
    const meshtrace::Image8 image = meshtrace::readImage(e.path());
    if (image.width != kWidth || image.height != kHeight) {
      std::fprintf(harnessLog, "%s reads back as %dx%d\n", e.path().c_str(), image.width,
                   image.height);
      std::abort();
    }
  }
  fs::current_path(before);
  return 0;
}
