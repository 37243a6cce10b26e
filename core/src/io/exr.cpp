#include "meshtrace/io/exr.h"

#include <ImfChannelList.h>
#include <ImfCompression.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "meshtrace/io/output_file.h"

namespace meshtrace {

namespace {
// OpenEXR writes through a seekable stream: this one keeps the bytes, which
// then go to the file whole through an OutputFile.
class MemoryStream : public Imf::OStream {
 public:
  MemoryStream() : Imf::OStream("memory") {}
  void write(const char c[], int n) override {
    const std::size_t end = position_ + static_cast<std::size_t>(n);
    if (bytes_.size() < end) bytes_.resize(end);
    std::memcpy(bytes_.data() + position_, c, static_cast<std::size_t>(n));
    position_ = end;
  }
  std::uint64_t tellp() override { return position_; }
  void seekp(std::uint64_t pos) override { position_ = static_cast<std::size_t>(pos); }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
  std::size_t position_ = 0;
};

Imf::Slice sliceOf(const ExrChannel& c, int width) {
  const bool isFloat = !c.floats.empty();
  const std::size_t size = isFloat ? sizeof(float) : sizeof(std::uint32_t);
  char* base = isFloat ? reinterpret_cast<char*>(const_cast<float*>(c.floats.data()))
                       : reinterpret_cast<char*>(const_cast<std::uint32_t*>(c.uints.data()));
  return Imf::Slice(isFloat ? Imf::FLOAT : Imf::UINT, base, size, size * width);
}
}  // namespace

const ExrChannel* ExrImage::find(const std::string& name) const {
  for (const ExrChannel& c : channels)
    if (c.name == name) return &c;
  return nullptr;
}

void writeExr(const ExrImage& image, const std::filesystem::path& path) {
  const std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
  std::string bytes;
  try {
    Imf::Header header(image.width, image.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    Imf::FrameBuffer frame;
    for (const ExrChannel& c : image.channels) {
      if ((c.floats.empty() ? c.uints.size() : c.floats.size()) != pixels)
        throw std::logic_error("channel " + c.name + " has the wrong size");
      header.channels().insert(c.name, Imf::Channel(c.floats.empty() ? Imf::UINT : Imf::FLOAT));
      frame.insert(c.name, sliceOf(c, image.width));
    }
    MemoryStream stream;
    {
      Imf::OutputFile file(stream, header);
      file.setFrameBuffer(frame);
      file.writePixels(image.height);
    }
    bytes = stream.bytes();
  } catch (const std::exception& e) {
    throw std::runtime_error(path.string() + ": cannot encode EXR: " + e.what());
  }
  writeFileAtomically(path, bytes);
}

ExrImage readExr(const std::filesystem::path& path) {
  try {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i window = file.header().dataWindow();
    ExrImage image;
    image.width = window.max.x - window.min.x + 1;
    image.height = window.max.y - window.min.y + 1;
    const std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
    for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it) {
      ExrChannel c;
      c.name = it.name();
      if (it.channel().type == Imf::UINT)
        c.uints.resize(pixels);
      else
        c.floats.resize(pixels);
      image.channels.push_back(std::move(c));
    }
    Imf::FrameBuffer frame;
    for (const ExrChannel& c : image.channels) {
      Imf::Slice slice = sliceOf(c, image.width);
      // The data window's origin maps to the vectors' start.
      slice.base -= (static_cast<std::ptrdiff_t>(window.min.y) * image.width + window.min.x) *
                    static_cast<std::ptrdiff_t>(slice.xStride);
      frame.insert(c.name, slice);
    }
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    return image;
  } catch (const std::exception& e) {
    throw std::runtime_error(path.string() + ": cannot read EXR: " + e.what());
  }
}

}  // namespace meshtrace
