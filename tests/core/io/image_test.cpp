// 8-bit quantization as the reference tools did it, image files, the atomic
// write, and image comparison.
#include "meshtrace/io/image.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "meshtrace/report/image_compare.h"
#include "support/file_size_limit.h"
#include "support/files.h"
#include "support/paths.h"

namespace meshtrace {
namespace {

// A small image with distinct values in every channel, so any mix-up of
// rows, columns or channels shows.
Image8 testPattern(int w = 5, int h = 3) {
  Image8 img{w, h, {}};
  for (int row = 0; row < h; ++row)
    for (int x = 0; x < w; ++x) {
      img.rgb.push_back(static_cast<std::uint8_t>(40 * x + 7));
      img.rgb.push_back(static_cast<std::uint8_t>(60 * row + 3));
      img.rgb.push_back(static_cast<std::uint8_t>(255 - 11 * (x + w * row)));
    }
  return img;
}

void expectSameImage(const Image8& a, const Image8& b) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  EXPECT_EQ(a.rgb, b.rgb);
}

// Runs writeImage and returns the message of the runtime_error it throws.
std::string writeErrorOf(const Image8& image, const std::filesystem::path& path) {
  try {
    writeImage(image, path);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  ADD_FAILURE() << "writing " << path << " should have failed";
  return "";
}

TEST(Quantize, TruncatesLike255TimesCFloored) {
  EXPECT_EQ(toByte(0.5), 127) << "127.5 is truncated, not rounded";
  EXPECT_EQ(toByte(0.999), 254);
  EXPECT_EQ(toByte(1.0), 255);
  EXPECT_EQ(toByte(1e-9), 0);
  for (int k = 0; k < 255; ++k) {
    EXPECT_EQ(toByte((k + 0.5) / 255.0), k);
    EXPECT_EQ(toByte((k + 0.999) / 255.0), k);
  }
}

TEST(Quantize, ClampsAndSendsNanToZero) {
  EXPECT_EQ(toByte(1.7), 255);
  EXPECT_EQ(toByte(kInfinity), 255);
  EXPECT_EQ(toByte(-0.3), 0);
  EXPECT_EQ(toByte(-kInfinity), 0);
  EXPECT_EQ(toByte(std::nan("")), 0);
  EXPECT_EQ(toByte(-std::nan("")), 0);
}

TEST(Quantize, KeepsRowsColumnsAndChannelsInPlace) {
  Image image(2, 2);
  image.at(0, 0) = Color(1.0, 0.0, 0.5);
  image.at(1, 0) = Color(0.2, 2.0, std::nan(""));
  image.at(0, 1) = Color(-1.0, 0.1, 0.9);
  image.at(1, 1) = Color(0.0);
  const Image8 q = quantize(image);
  ASSERT_EQ(q.rgb.size(), 12u);
  EXPECT_EQ(q.channel(0, 0, 2), 127);
  EXPECT_EQ(q.channel(1, 0, 0), 51);
  EXPECT_EQ(q.channel(1, 0, 1), 255);
  EXPECT_EQ(q.channel(1, 0, 2), 0);
  EXPECT_EQ(q.channel(0, 1, 0), 0);
  EXPECT_EQ(q.channel(0, 1, 2), 229);
}

class LosslessFormat : public ::testing::TestWithParam<const char*> {};

TEST_P(LosslessFormat, WritesWhatReadsBackExactly) {
  const auto path = test::scratchDir() / (std::string("img") + GetParam());
  writeImage(testPattern(), path);
  expectSameImage(readImage(path), testPattern());
}

INSTANTIATE_TEST_SUITE_P(Extensions, LosslessFormat,
                         ::testing::Values(".png", ".bmp", ".ppm", ".PNG"), [](const auto& info) {
                           std::string s = info.param + 1;
                           return s;
                         });

// A render-sized image of noise and flat runs: zlib's output then spans
// many buffers of the encoder's write callback.
TEST(WriteImage, PngOfARenderSizedImageReadsBackExactly) {
  Image8 image{800, 600, {}};
  image.rgb.resize(800 * 600 * 3);
  std::uint32_t state = 12345;
  for (std::size_t i = 0; i < image.rgb.size(); ++i) {
    state = state * 1664525u + 1013904223u;
    image.rgb[i] = (i / 3) % 800 < 400 ? static_cast<std::uint8_t>(state >> 24) : 40;
  }
  const auto path = test::scratchDir() / "render.png";
  writeImage(image, path);
  expectSameImage(readImage(path), image);
}

// libpng refuses a zero-sized image; its reason reaches the caller and no
// file is left behind.
TEST(WriteImage, AnEmptyPngIsRefusedWithTheEncodersReason) {
  const auto path = test::scratchDir() / "empty.png";
  try {
    writeImage(Image8{0, 0, {}}, path);
    FAIL() << "an empty image was written";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("IHDR"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(WriteImage, PpmIsBinaryP6TopRowFirst) {
  const auto path = test::scratchDir() / "img.ppm";
  writeImage(testPattern(2, 3), path);
  const std::string bytes = test::readFileBytes(path);
  const std::string header = "P6\n2 3\n255\n";
  ASSERT_EQ(bytes.size(), header.size() + 2 * 3 * 3);
  EXPECT_EQ(bytes.substr(0, header.size()), header);
  EXPECT_EQ(static_cast<std::uint8_t>(bytes[header.size() + 1]), 3) << "row 0 first";
}

TEST(WriteImage, JpegIsCloseToTheOriginal) {
  const auto path = test::scratchDir() / "img.jpg";
  Image8 flat{16, 16, std::vector<std::uint8_t>(16 * 16 * 3, 100)};
  writeImage(flat, path);
  const Image8 back = readImage(path);
  ASSERT_EQ(back.width, 16);
  EXPECT_LE(compareImages(back, flat).maxDifference, 1);
}

TEST(WriteImage, ReplacesAnExistingFileAndLeavesNoTemporary) {
  const auto dir = test::scratchDir();
  test::writeFile(dir / "out.png", "old contents");
  writeImage(testPattern(), dir / "out.png");
  expectSameImage(readImage(dir / "out.png"), testPattern());
  EXPECT_EQ(test::listFolder(dir), std::vector<std::string>{"out.png"});
}

TEST(WriteImage, RefusesAnUnknownExtensionLeavingTheOldFile) {
  const auto dir = test::scratchDir();
  test::writeFile(dir / "out.gif", "old contents");
  test::expectMentions(writeErrorOf(testPattern(), dir / "out.gif"), {"out.gif", ".gif"});
  EXPECT_EQ(test::readFileBytes(dir / "out.gif"), "old contents");
  test::expectMentions(writeErrorOf(testPattern(), dir / "noextension"), {"noextension"});
  EXPECT_EQ(test::listFolder(dir), std::vector<std::string>{"out.gif"});
}

TEST(WriteImage, FailsInAMissingFolder) {
  const auto dir = test::scratchDir();
  test::expectMentions(writeErrorOf(testPattern(), dir / "missing" / "out.png"), {"out.png"});
  EXPECT_TRUE(test::listFolder(dir).empty());
}

TEST(WriteImage, FailsWhenTheTargetIsAFolderLeavingItAlone) {
  const auto dir = test::scratchDir();
  std::filesystem::create_directory(dir / "out.png");
  test::writeFile(dir / "out.png" / "keep", "x");
  test::expectMentions(writeErrorOf(testPattern(), dir / "out.png"), {"out.png"});
  EXPECT_EQ(test::readFileBytes(dir / "out.png" / "keep"), "x");
  EXPECT_EQ(test::listFolder(dir), std::vector<std::string>{"out.png"}) << "no temporary left";
}

TEST(WriteImage, FailsBelowARegularFile) {
  const auto dir = test::scratchDir();
  test::writeFile(dir / "file", "x");
  test::expectMentions(writeErrorOf(testPattern(), dir / "file" / "out.ppm"), {"out.ppm"});
}

// A write that fails half way (here: the file size limit is reached) must
// leave the previous file as it was and no partial file behind.
TEST(WriteImage, AFailureHalfWayLeavesTheOldFileUntouched) {
  const auto dir = test::scratchDir();
  const std::string old(200, 'o');
  test::writeFile(dir / "out.ppm", old);
  test::writeFile(dir / "out.bmp", old);
  test::writeFile(dir / "out.png", old);
  // Pseudo-random pixels: 30 kB that no encoder squeezes under the limit.
  Image8 big{100, 100, std::vector<std::uint8_t>(100 * 100 * 3)};
  std::mt19937 random(7);
  for (std::uint8_t& byte : big.rgb) byte = static_cast<std::uint8_t>(random() >> 24);
  {
    test::FileSizeLimit limit(1000);
    ASSERT_TRUE(limit.ok());
    for (const char* name : {"out.ppm", "out.bmp", "out.png"}) {
      EXPECT_THROW(writeImage(big, dir / name), std::runtime_error) << name;
    }
  }
  EXPECT_TRUE(test::readFileBytes(dir / "out.ppm") == old) << "the old PPM was replaced";
  EXPECT_TRUE(test::readFileBytes(dir / "out.bmp") == old) << "the old BMP was replaced";
  EXPECT_TRUE(test::readFileBytes(dir / "out.png") == old) << "the old PNG was replaced";
  EXPECT_EQ(test::listFolder(dir), (std::vector<std::string>{"out.bmp", "out.png", "out.ppm"}));
}

TEST(ReadImage, NamesAMissingOrCorruptFile) {
  const auto dir = test::scratchDir();
  try {
    readImage(dir / "absent.png");
    ADD_FAILURE() << "reading a missing file should fail";
  } catch (const std::runtime_error& e) {
    test::expectMentions(e.what(), {"absent.png"});
  }
  test::writeFile(dir / "junk.png", "not an image at all");
  EXPECT_THROW(readImage(dir / "junk.png"), std::runtime_error);
  test::writeFile(dir / "cut.jpg", std::string("\xff\xd8\xff\xe0\0\x10JFIF", 10));
  EXPECT_THROW(readImage(dir / "cut.jpg"), std::runtime_error);
}

TEST(JpegRoundTrip, KeepsTheSizeAndStaysClose) {
  const Image8 img = testPattern(24, 17);
  const Image8 back = jpegRoundTrip(img, 95);
  ASSERT_EQ(back.width, 24);
  ASSERT_EQ(back.height, 17);
  EXPECT_LT(compareImages(img, back).rmse, 8.0);
}

TEST(CompareImages, IdenticalImagesDifferByNothing) {
  const ImageDifference d = compareImages(testPattern(), testPattern());
  EXPECT_EQ(d.rmse, 0.0);
  EXPECT_EQ(d.maxDifference, 0);
  EXPECT_EQ(d.fractionOver32, 0.0);
  EXPECT_TRUE(std::isinf(d.psnr));
}

TEST(CompareImages, MeasuresRmseOverAllChannelsAndCountsPixelsOver32) {
  Image8 a{2, 2, std::vector<std::uint8_t>(12, 100)};
  Image8 b = a;
  b.rgb[0] = 103;  // pixel 0: off by 3 in one channel
  b.rgb[10] = 60;  // pixel 3: off by 40
  const ImageDifference d = compareImages(a, b);
  EXPECT_NEAR(d.rmse, std::sqrt((9.0 + 1600.0) / 12.0), 1e-12);
  EXPECT_EQ(d.maxDifference, 40);
  EXPECT_EQ(d.fractionOver32, 0.25);
  EXPECT_NEAR(d.psnr, 20 * std::log10(255.0 / d.rmse), 1e-12);
}

TEST(CompareImages, ThirtyTwoExactlyIsNotOver) {
  Image8 a{1, 1, {0, 0, 0}};
  Image8 b{1, 1, {32, 0, 0}};
  EXPECT_EQ(compareImages(a, b).fractionOver32, 0.0);
}

TEST(CompareImages, RefusesDifferentSizes) {
  EXPECT_THROW(compareImages(testPattern(5, 3), testPattern(3, 5)), std::invalid_argument);
}

}  // namespace
}  // namespace meshtrace
