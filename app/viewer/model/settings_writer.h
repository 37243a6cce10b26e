#pragma once
// Writes the viewer's settings file (saveSettings) on a thread of its own.
// A safe write ends in fdatasync, which waits for the disk; while the disk
// is busy (a render's output being written back, say) that wait can last
// many frames, and the UI thread saves the settings when a scene opens or
// a panel is resized. Writes happen in the order asked, a newer request
// replacing one still waiting; what is waiting when the writer is
// destroyed is written before it goes.
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>

#include "viewer/model/serial_worker.h"
#include "viewer/model/settings.h"

namespace meshtrace::viewer {

class SettingsWriter {
 public:
  void save(const ViewerSettings& settings, const std::filesystem::path& file);
  // Waits until every request so far is written.
  void flush() { worker_.flush(); }
  // Why the last write that failed did, once; else empty.
  std::string takeError();

 private:
  struct Request {
    ViewerSettings settings;
    std::filesystem::path file;
  };
  void writePending();

  std::mutex mutex_;
  std::optional<Request> pending_;  // the newest request not yet taken by a write
  std::string error_;
  SerialWorker worker_;  // last: it goes first, writing what is pending
};

}  // namespace meshtrace::viewer
