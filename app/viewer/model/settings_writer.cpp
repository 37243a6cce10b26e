#include "viewer/model/settings_writer.h"

#include <exception>
#include <utility>

namespace meshtrace::viewer {

void SettingsWriter::save(const ViewerSettings& settings, const std::filesystem::path& file) {
  bool writeQueued;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    writeQueued = pending_.has_value();
    pending_ = Request{settings, file};
  }
  // A write already queued takes this request in place of the one before.
  if (!writeQueued) worker_.post([this] { writePending(); });
}

std::string SettingsWriter::takeError() {
  std::lock_guard<std::mutex> lock(mutex_);
  return std::exchange(error_, std::string());
}

void SettingsWriter::writePending() {
  Request request;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    request = std::move(*pending_);
    pending_.reset();
  }
  std::string error;
  try {
    saveSettings(request.settings, request.file);
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (error.empty()) return;
  std::lock_guard<std::mutex> lock(mutex_);
  error_ = std::move(error);
}

}  // namespace meshtrace::viewer
