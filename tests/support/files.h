#pragma once
// Small file helpers for tests that write inputs to a scratch folder and
// check what a tool left behind.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace meshtrace::test {

// Writes `content` byte for byte (no newline translation) and returns the path.
std::filesystem::path writeFile(const std::filesystem::path& path, std::string_view content);

// The whole file, or an empty string if it is not a readable regular file.
std::string readFileBytes(const std::filesystem::path& path);

// Names of the entries directly inside `dir`, sorted: shows stray temporary
// files a failed write might leave.
std::vector<std::string> listFolder(const std::filesystem::path& dir);

// Fails the current test unless `message` contains every one of `parts`.
void expectMentions(const std::string& message, std::initializer_list<std::string_view> parts);

}  // namespace meshtrace::test
