#pragma once
// Checks shared by the command-line tool tests: a run on bad input must end
// cleanly (an exit code, not a signal or a hang), say what is wrong on
// stderr, and leave an existing output file exactly as it was.
#include <filesystem>
#include <string>
#include <vector>

#include "support/bad_inputs.h"
#include "support/run_tool.h"

namespace meshtrace::test {

inline std::filesystem::path raytraceTool() { return MESHTRACE_RAYTRACE; }
inline std::filesystem::path debugAabbTool() { return MESHTRACE_DEBUG_AABB; }
inline std::filesystem::path makeScenesTool() { return MESHTRACE_MAKE_SCENES; }

// What an existing output file holds before a run that must not touch it.
inline const std::string kOldOutput = "previous output, must survive a failed run";

// Runs `tool args...` in `dir` and checks a clean refusal: exit code 1 (not
// a signal or a hang), "error" and every one of `mentions` on stderr,
// `output` byte for byte as before (if it existed) and no file added to or
// removed from `dir`.
ToolResult expectRefusal(const std::filesystem::path& tool, const std::vector<std::string>& args,
                         const std::filesystem::path& dir, const std::vector<std::string>& mentions,
                         const std::filesystem::path& output);

// Writes the case's bad.sce and mesh.off (and an empty folder.off/) into a
// scratch folder beside an existing out.png, runs `tool bad.sce out.png`
// and expects a clean refusal.
void expectRefusesBadInput(const std::filesystem::path& tool, const BadInput& input);

// A scratch folder holding good.sce (a sphere and a one-triangle mesh,
// 8x6 pixels) and its mesh, tri.off.
std::filesystem::path folderWithGoodScene();
// `dir`/good.sce and `dir`/`out`: the arguments that render one to the other.
std::vector<std::string> renderArgs(const std::filesystem::path& dir, const std::string& out);

// An output that cannot be written is refused before the scene is loaded
// and rendered, not after a long render.
void expectRefusedBeforeRendering(const ToolResult& r);

// Runs `tool args...` in `dir` and checks that it succeeded.
ToolResult expectSuccess(const std::filesystem::path& tool, const std::vector<std::string>& args,
                         const std::filesystem::path& dir);

// Runs the shell `command` in `dir` with its stdout and stderr on a
// pseudo-terminal (made by script(1)), as a user at a terminal would;
// what it printed, both streams, is in `out`.
ToolResult runOnTerminal(const std::string& command, const std::filesystem::path& dir);

}  // namespace meshtrace::test
