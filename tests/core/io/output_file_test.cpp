// Files written whole or not at all: the temporary's name and creation,
// what the folder holds before and after a commit, failures half way, sets
// of files committed together, and a signal during a write.
#include "meshtrace/io/output_file.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <functional>
#include <set>
#include <stdexcept>

#include "io/temporaries.h"
#include "support/file_size_limit.h"
#include "support/files.h"
#include "support/paths.h"

namespace meshtrace {
namespace {

std::string writeErrorOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  ADD_FAILURE() << "the write should have failed";
  return "";
}

TEST(TemporaryName, IsHiddenUnpredictableAndFitsBesideTheLongestName) {
  const std::string longest(251, 'n');
  std::set<std::string> names;
  for (int i = 0; i < 1000; ++i) {
    const std::string name = temporaries::name(longest + ".png", 255);
    EXPECT_LE(name.size(), 255u);
    EXPECT_EQ(name.front(), '.');
    EXPECT_EQ(name.substr(name.size() - 4), ".tmp");
    EXPECT_EQ(name.find('/'), std::string::npos);
    names.insert(name);
  }
  EXPECT_EQ(names.size(), 1000u) << "every temporary gets a name of its own";
  EXPECT_LE(temporaries::name(longest, 40).size(), 40u) << "a file system of short names";
}

TEST(TemporaryName, CutsTheTargetsNameAtACharacterBoundary) {
  std::string name;
  for (int i = 0; i < 40; ++i) name += "\xc3\xa9";  // é, two bytes each
  const std::string temporary = temporaries::name(name, 255);
  const std::string prefix = temporary.substr(1, temporary.find('.', 1) - 1);
  EXPECT_EQ(prefix.size() % 2, 0u) << "no é cut in half";
}

TEST(CreateExclusive, NeverOpensThroughAPlantedSymlink) {
  const auto dir = test::scratchDir();
  test::writeFile(dir / "victim", "precious");
  std::filesystem::create_symlink(dir / "victim", dir / ".planted.tmp");
  std::filesystem::create_symlink(dir / "nowhere", dir / ".dangling.tmp");
  const int folder = ::open(dir.c_str(), O_PATH | O_DIRECTORY);
  ASSERT_GE(folder, 0);
  for (const char* name : {".planted.tmp", ".dangling.tmp"}) {
    errno = 0;
    EXPECT_LT(temporaries::createExclusive(folder, name), 0) << name;
    EXPECT_EQ(errno, EEXIST) << name;
  }
  ::close(folder);
  EXPECT_EQ(test::readFileBytes(dir / "victim"), "precious");
  EXPECT_FALSE(std::filesystem::exists(dir / "nowhere"));
}

TEST(OutputFile, ReplacesTheTargetOnlyWhenCommitted) {
  const auto dir = test::scratchDir();
  test::writeFile(dir / "out.txt", "old");
  OutputFile out(dir / "out.txt");
  out.write("new ");
  out.write(std::string(200000, 'x'));  // more than the buffer holds
  EXPECT_EQ(test::readFileBytes(dir / "out.txt"), "old");
  const auto during = test::listFolder(dir);
  ASSERT_EQ(during.size(), 2u);
  EXPECT_EQ(during[0].front(), '.') << "the temporary is hidden, in the same folder";
  out.commit();
  EXPECT_EQ(test::readFileBytes(dir / "out.txt"), "new " + std::string(200000, 'x'));
  EXPECT_EQ(test::listFolder(dir), std::vector<std::string>{"out.txt"});
}

TEST(OutputFile, DroppedUnfinishedLeavesTheOldFileAndNoTemporary) {
  const auto dir = test::scratchDir();
  test::writeFile(dir / "out.txt", "old");
  {
    OutputFile out(dir / "out.txt");
    out.write("half");
  }
  {
    OutputFile out(dir / "out.txt");
    out.write("finished, never renamed");
    out.finish();
  }
  EXPECT_EQ(test::readFileBytes(dir / "out.txt"), "old");
  EXPECT_EQ(test::listFolder(dir), std::vector<std::string>{"out.txt"});
}

TEST(OutputFile, ReplacesASymlinkWithoutWritingWhereItPoints) {
  const auto dir = test::scratchDir();
  test::writeFile(dir / "elsewhere", "precious");
  std::filesystem::create_symlink("elsewhere", dir / "out.txt");
  writeFileAtomically(dir / "out.txt", "new");
  EXPECT_FALSE(std::filesystem::is_symlink(dir / "out.txt"));
  EXPECT_EQ(test::readFileBytes(dir / "out.txt"), "new");
  EXPECT_EQ(test::readFileBytes(dir / "elsewhere"), "precious");
}

TEST(OutputFile, TakesTheLongestNameItsFileSystemAllows) {
  const auto dir = test::scratchDir();
  const std::string longest(255, 'n');
  writeFileAtomically(dir / longest, "fits");
  EXPECT_EQ(test::readFileBytes(dir / longest), "fits");
  test::expectMentions(writeErrorOf([&] { writeFileAtomically(dir / (longest + "n"), "x"); }),
                       {"256 bytes", "255"});
  EXPECT_EQ(test::listFolder(dir), std::vector<std::string>{longest});
}

TEST(OutputFile, RefusesMissingFoldersFilesInTheWayAndFolderTargets) {
  const auto dir = test::scratchDir();
  test::writeFile(dir / "file", "x");
  std::filesystem::create_directory(dir / "folder");
  test::expectMentions(writeErrorOf([&] { OutputFile(dir / "missing" / "out"); }),
                       {"out", "no folder", "missing"});
  test::expectMentions(writeErrorOf([&] { OutputFile(dir / "file" / "out"); }),
                       {"out", "not a folder"});
  test::expectMentions(writeErrorOf([&] { OutputFile(dir / "folder"); }),
                       {"folder", "is a folder"});
  test::expectMentions(writeErrorOf([&] { OutputFile(dir / "folder/"); }), {"folder"});
  EXPECT_EQ(test::listFolder(dir), (std::vector<std::string>{"file", "folder"}));
}

TEST(OutputFile, AFileSizeLimitFailsTheWriteLeavingTheOldFile) {
  const auto dir = test::scratchDir();
  test::writeFile(dir / "out.bin", "old");
  std::string message;
  {
    test::FileSizeLimit limit(1000);
    ASSERT_TRUE(limit.ok());
    message = writeErrorOf([&] { writeFileAtomically(dir / "out.bin", std::string(300000, 'x')); });
  }
  test::expectMentions(message, {"out.bin", "file size limit"});
  EXPECT_EQ(test::readFileBytes(dir / "out.bin"), "old");
  EXPECT_EQ(test::listFolder(dir), std::vector<std::string>{"out.bin"});
}

TEST(CommitTogether, ReplacesNoTargetUnlessAllAreWritten) {
  const auto dir = test::scratchDir();
  test::writeFile(dir / "a.txt", "old a");
  test::writeFile(dir / "b.txt", "old b");
  std::string message;
  {
    test::FileSizeLimit limit(1000);
    ASSERT_TRUE(limit.ok());
    message = writeErrorOf([&] {
      std::vector<OutputFile> files;
      files.emplace_back(dir / "a.txt").write("new a");
      files.emplace_back(dir / "b.txt").write(std::string(300000, 'b'));
      commitTogether(files);
    });
  }
  test::expectMentions(message, {"b.txt"});
  EXPECT_EQ(test::readFileBytes(dir / "a.txt"), "old a");
  EXPECT_EQ(test::readFileBytes(dir / "b.txt"), "old b");
  EXPECT_EQ(test::listFolder(dir), (std::vector<std::string>{"a.txt", "b.txt"}));

  std::vector<OutputFile> files;
  files.emplace_back(dir / "a.txt").write("new a");
  files.emplace_back(dir / "b.txt").write("new b");
  commitTogether(files);
  EXPECT_EQ(test::readFileBytes(dir / "a.txt"), "new a");
  EXPECT_EQ(test::readFileBytes(dir / "b.txt"), "new b");
}

// A process that a signal ends in the middle of a write: the temporary
// goes with it, and the signal still ends it (as its default action would).
void expectSignalRemovesTheTemporary(int signal) {
  const auto dir = test::scratchDir();
  test::writeFile(dir / "out.txt", "old");
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    OutputFile out(dir / "out.txt");
    out.write(std::string(300000, 'x'));
    ::raise(signal);
    ::_exit(0);  // not reached: the signal ends the process
  }
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the child exited with " << WEXITSTATUS(status);
  EXPECT_EQ(WTERMSIG(status), signal);
  EXPECT_EQ(test::readFileBytes(dir / "out.txt"), "old");
  EXPECT_EQ(test::listFolder(dir), std::vector<std::string>{"out.txt"});
}

TEST(OutputFile, SigintDuringAWriteRemovesTheTemporary) { expectSignalRemovesTheTemporary(SIGINT); }
TEST(OutputFile, SigtermDuringAWriteRemovesTheTemporary) {
  expectSignalRemovesTheTemporary(SIGTERM);
}
TEST(OutputFile, SighupDuringAWriteRemovesTheTemporary) { expectSignalRemovesTheTemporary(SIGHUP); }

}  // namespace
}  // namespace meshtrace
