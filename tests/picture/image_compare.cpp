#include "image_compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <stdexcept>

namespace bookspin::picture {

namespace {

/// Largest of the four channel differences of pixel `i`.
int pixel_difference(const RgbaImage& a, const RgbaImage& b, std::size_t i) {
  int largest = 0;
  for (std::size_t c = 0; c < 4; ++c) {
    largest = std::max(largest, std::abs(int(a.pixels[4 * i + c]) - int(b.pixels[4 * i + c])));
  }
  return largest;
}

double squared_rgb_error(const RgbaImage& a, const RgbaImage& b, std::size_t i) {
  double sum = 0;
  for (std::size_t c = 0; c < 3; ++c) {
    const double d = double(a.pixels[4 * i + c]) - double(b.pixels[4 * i + c]);
    sum += d * d;
  }
  return sum;
}

double psnr(double squared_error_sum, std::size_t samples) {
  if (squared_error_sum == 0) return std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(255.0 * 255.0 * double(samples) / squared_error_sum);
}

bool same_size(const RgbaImage& a, const RgbaImage& b) {
  return a.width == b.width && a.height == b.height && a.pixels.size() == b.pixels.size() &&
         a.pixels.size() == std::size_t(a.width) * a.height * 4;
}

}  // namespace

std::string Comparison::summary(const Tolerance& tolerance) const {
  if (!same_size) return "the images differ in size";
  char text[200];
  std::snprintf(text, sizeof text,
                "PSNR %.1f dB, %.2f%% of pixels differ by > %d/255 (allowed %.2f%%), max %d/255",
                psnr_db, 100 * differing_fraction, tolerance.channel_threshold,
                100 * tolerance.max_differing_fraction, max_channel_difference);
  return text;
}

Comparison compare_images(const RgbaImage& actual, const RgbaImage& expected,
                          const Tolerance& tolerance) {
  Comparison result;
  result.same_size = same_size(actual, expected);
  if (!result.same_size) {
    result.differing_fraction = 1.0;
    return result;
  }
  const std::size_t count = std::size_t(actual.width) * actual.height;
  double squared_error = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const int difference = pixel_difference(actual, expected, i);
    result.max_channel_difference = std::max(result.max_channel_difference, difference);
    if (difference > tolerance.channel_threshold) ++result.differing_pixels;
    squared_error += squared_rgb_error(actual, expected, i);
  }
  result.differing_fraction = count == 0 ? 0.0 : double(result.differing_pixels) / double(count);
  result.psnr_db = psnr(squared_error, 3 * count);
  result.passed = result.differing_fraction <= tolerance.max_differing_fraction;
  return result;
}

RgbaImage diff_image(const RgbaImage& actual, const RgbaImage& expected,
                     const Tolerance& tolerance) {
  if (!same_size(actual, expected))
    throw std::invalid_argument("diff_image: the images differ in size");
  RgbaImage diff(actual.width, actual.height);
  for (std::size_t i = 0; i < std::size_t(actual.width) * actual.height; ++i) {
    const std::uint8_t* e = &expected.pixels[4 * i];
    const auto ghost = std::uint8_t(32 + (e[0] + e[1] + e[2]) / 12);  // faint: 32…95
    const int difference = pixel_difference(actual, expected, i);
    std::uint8_t* d = &diff.pixels[4 * i];
    d[0] = d[1] = d[2] = ghost;
    if (difference > tolerance.channel_threshold) {
      d[0] = std::uint8_t(std::min(255, 160 + difference));
      d[1] = d[2] = 0;
    } else if (difference > 0) {
      d[2] = 220;
    }
    d[3] = 255;
  }
  return diff;
}

RgbaImage mirrored(const RgbaImage& image) {
  RgbaImage out(image.width, image.height);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      std::copy_n(image.row(y) + 4 * x, 4, out.row(y) + 4 * (image.width - 1 - x));
    }
  }
  return out;
}

}  // namespace bookspin::picture
