#include "viewer/model/settings_writer.h"

#include <exception>
#include <utility>

namespace meshtrace::viewer {

SettingsWriter::~SettingsWriter() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void SettingsWriter::save(const ViewerSettings& settings, const std::filesystem::path& file) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    pending_ = Request{settings, file};
    if (!thread_.joinable()) thread_ = std::thread([this] { run(); });
  }
  changed_.notify_all();
}

void SettingsWriter::flush() {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [&] { return !pending_ && !writing_; });
}

std::string SettingsWriter::takeError() {
  std::lock_guard<std::mutex> lock(mutex_);
  return std::exchange(error_, std::string());
}

void SettingsWriter::run() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return pending_ || stopping_; });
    // What is waiting is written even when stopping: the last settings of
    // a closing window are kept.
    if (!pending_) return;
    Request request = std::move(*pending_);
    pending_.reset();
    writing_ = true;
    lock.unlock();
    std::string error;
    try {
      saveSettings(request.settings, request.file);
    } catch (const std::exception& e) {
      error = e.what();
    }
    lock.lock();
    writing_ = false;
    if (!error.empty()) error_ = std::move(error);
    changed_.notify_all();
  }
}

}  // namespace meshtrace::viewer
