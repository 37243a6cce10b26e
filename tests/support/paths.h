#pragma once
// Where tests find the project tree, the seed data and the built tools.
#include <gtest/gtest.h>

#include <filesystem>

namespace meshtrace::test {

inline std::filesystem::path sourceDir() { return MESHTRACE_SOURCE_DIR; }

// ../shared/seed beside the checkout, when present.
inline std::filesystem::path seedDir() { return sourceDir().parent_path() / "shared" / "seed"; }
inline bool haveSeed() { return std::filesystem::is_directory(seedDir() / "scenes"); }

// A fresh, empty folder for one test's files.
std::filesystem::path scratchDir();

}  // namespace meshtrace::test

// Skips the current test, saying why, when the seed data is absent.
#define MESHTRACE_REQUIRE_SEED()                                                       \
  do {                                                                                 \
    if (!::meshtrace::test::haveSeed())                                                \
      GTEST_SKIP() << "seed data not found at " << ::meshtrace::test::seedDir()        \
                   << ": skipping the conformance check against the reference images"; \
  } while (0)
