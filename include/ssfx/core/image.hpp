// Image types: owning Image<T> and non-owning ImageView<T>.
//
// Conventions (DESIGN.md): row-major, row 0 is the top row (the first row in a file),
// pixel (x, y) has its centre at (x + 0.5, y + 0.5). Strides are in elements, so a view
// can address a sub-rectangle. Colour is 8-bit RGBA unorm (no sRGB decoding anywhere in
// the anti-aliasing code: the filters work on stored values, as a GPU does with
// rgba8unorm); depth/z/AO planes are float32.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include "ssfx/core/error.hpp"

namespace ssfx {

struct Rgba8 {
    std::uint8_t r = 0, g = 0, b = 0, a = 0;
    friend bool operator==(const Rgba8&, const Rgba8&) = default;
};
static_assert(sizeof(Rgba8) == 4, "Rgba8 must be tightly packed");

//! Largest image accepted anywhere (width * height), checked before allocating.
//! 2^28 pixels = 1 GiB of RGBA8; beyond that a request is almost surely a corrupt header.
inline constexpr std::int64_t kMaxPixels = std::int64_t{1} << 28;
//! Largest single dimension accepted (also keeps x * 256 sub-texel arithmetic in int32).
inline constexpr int kMaxDimension = 1 << 20;

//! Throws ssfx::Error unless 1 <= width, height <= kMaxDimension and width*height <= kMaxPixels.
//! `what` names the image in the message (a file name, "input", ...).
void checkDimensions(std::int64_t width, std::int64_t height, const std::string& what);

template <class T>
class ImageView {
public:
    using Pixel = std::remove_const_t<T>;
    ImageView() = default;
    ImageView(T* data, int width, int height, std::ptrdiff_t stride)
        : data_(data), width_(width), height_(height), stride_(stride) {}
    ImageView(T* data, int width, int height) : ImageView(data, width, height, width) {}
    //! A view of non-const pixels converts to a view of const pixels.
    template <class U, class = std::enable_if_t<std::is_same_v<T, const U>>>
    ImageView(const ImageView<U>& o)  // NOLINT(google-explicit-constructor)
        : data_(o.data()), width_(o.width()), height_(o.height()), stride_(o.stride()) {}

    int width() const { return width_; }
    int height() const { return height_; }
    std::ptrdiff_t stride() const { return stride_; }
    std::int64_t pixelCount() const { return std::int64_t{width_} * height_; }
    bool empty() const { return width_ <= 0 || height_ <= 0; }
    T* data() const { return data_; }
    T* row(int y) const { return data_ + y * stride_; }
    T& operator()(int x, int y) const { return data_[y * stride_ + x]; }
    //! Clamp-to-edge access.
    T& clamped(int x, int y) const {
        x = x < 0 ? 0 : (x >= width_ ? width_ - 1 : x);
        y = y < 0 ? 0 : (y >= height_ ? height_ - 1 : y);
        return (*this)(x, y);
    }

private:
    T* data_ = nullptr;
    int width_ = 0, height_ = 0;
    std::ptrdiff_t stride_ = 0;
};

template <class T>
class Image {
public:
    Image() = default;
    //! Allocates width x height pixels initialised to `fill`; validates the size first.
    Image(int width, int height, T fill = T{}) : width_(width), height_(height) {
        checkDimensions(width, height, "image");
        pixels_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), fill);
    }
    //! Deep copy of a view.
    static Image copyOf(ImageView<const T> v) {
        Image out(v.width(), v.height());
        for (int y = 0; y < v.height(); ++y) std::copy(v.row(y), v.row(y) + v.width(), out.view().row(y));
        return out;
    }

    int width() const { return width_; }
    int height() const { return height_; }
    std::int64_t pixelCount() const { return std::int64_t{width_} * height_; }
    bool empty() const { return pixels_.empty(); }
    T* data() { return pixels_.data(); }
    const T* data() const { return pixels_.data(); }
    T& operator()(int x, int y) { return pixels_[std::size_t(y) * width_ + x]; }
    const T& operator()(int x, int y) const { return pixels_[std::size_t(y) * width_ + x]; }
    ImageView<T> view() { return {pixels_.data(), width_, height_, width_}; }
    ImageView<const T> view() const { return {pixels_.data(), width_, height_, width_}; }
    operator ImageView<const T>() const { return view(); }  // NOLINT
    const std::vector<T>& pixels() const { return pixels_; }
    friend bool operator==(const Image& a, const Image& b) {
        return a.width_ == b.width_ && a.height_ == b.height_ && a.pixels_ == b.pixels_;
    }

private:
    int width_ = 0, height_ = 0;
    std::vector<T> pixels_;
};

using ImageRgba8 = Image<Rgba8>;
using ImageF = Image<float>;

}  // namespace ssfx
