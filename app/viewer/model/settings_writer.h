#pragma once
// Writes the viewer's settings file (saveSettings) on a thread of its own.
// A safe write ends in fdatasync, which waits for the disk; while the disk
// is busy (a render's output being written back, say) that wait can last
// many frames, and the UI thread saves the settings when a scene opens or
// a panel is resized. Writes happen in the order asked, a newer request
// replacing one still waiting; what is waiting when the writer is
// destroyed is written before it goes.
#include <condition_variable>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "viewer/model/settings.h"

namespace meshtrace::viewer {

class SettingsWriter {
 public:
  SettingsWriter() = default;
  ~SettingsWriter();
  SettingsWriter(const SettingsWriter&) = delete;
  SettingsWriter& operator=(const SettingsWriter&) = delete;

  void save(const ViewerSettings& settings, const std::filesystem::path& file);
  // Waits until every request so far is written.
  void flush();
  // Why the last write that failed did, once; else empty.
  std::string takeError();

 private:
  struct Request {
    ViewerSettings settings;
    std::filesystem::path file;
  };
  void run();

  std::mutex mutex_;
  std::condition_variable changed_;
  std::optional<Request> pending_;
  bool writing_ = false;
  bool stopping_ = false;
  std::string error_;
  std::thread thread_;  // started with the first request
};

}  // namespace meshtrace::viewer
