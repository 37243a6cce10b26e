#include "bench/full_run.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <vector>

#include "bench/embree_intersector.h"
#include "meshtrace/io/image.h"
#include "meshtrace/io/scene_parser.h"
#include "meshtrace/render/render.h"

extern char** environ;

namespace meshtrace::bench {

namespace {

// Embree's hits are float: shading spawns rays as for a float kernel.
TraceOptions singlePrecisionHits() {
  TraceOptions o;
  o.triangle.precision = Precision::Single;
  return o;
}

struct WithEmbree {
  EmbreeIntersector embree;
  SceneIntersector intersector;
  explicit WithEmbree(const Scene& s)
      : embree(s, RTC_BUILD_QUALITY_MEDIUM), intersector(s, singlePrecisionHits(), embree) {}
};

}  // namespace

double fullRunHereMs(const Engine& engine, const std::filesystem::path& scene,
                     const std::filesystem::path& image, int threads) {
  const auto start = std::chrono::steady_clock::now();
  const Scene loaded = loadScene(scene);
  std::unique_ptr<WithEmbree> embree;
  std::unique_ptr<SceneIntersector> ours;
  if (engine == "embree") {
    embree = std::make_unique<WithEmbree>(loaded);
  } else {
    TraceOptions options;
    options.accel = parseAccelMethod(engine);
    ours = std::make_unique<SceneIntersector>(loaded, options);
  }
  const Image rendered = render(embree ? embree->intersector : *ours, threads);
  writeImage(quantize(rendered), image);
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

double fullRunMs(const Engine& engine, const std::filesystem::path& scene,
                 const std::filesystem::path& image, int threads) {
  std::vector<std::string> args = {"bench",
                                   "--full-run",
                                   engine,
                                   "--image",
                                   image.string(),
                                   "--threads",
                                   std::to_string(threads),
                                   scene.string()};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  int out[2];
  if (pipe(out) != 0) throw std::runtime_error("full run: no pipe");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
  posix_spawn_file_actions_addclose(&actions, out[0]);
  pid_t child = 0;
  const int spawned =
      posix_spawn(&child, "/proc/self/exe", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(out[1]);
  std::string printed;
  char buf[256];
  for (ssize_t n; spawned == 0 && (n = read(out[0], buf, sizeof buf)) > 0;) printed.append(buf, n);
  close(out[0]);
  int status = 0;
  if (spawned != 0 || waitpid(child, &status, 0) != child || !WIFEXITED(status) ||
      WEXITSTATUS(status) != 0)
    throw std::runtime_error("full run of " + scene.string() + " by " + engine + " failed");
  return std::strtod(printed.c_str(), nullptr);
}

}  // namespace meshtrace::bench
