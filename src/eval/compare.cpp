#include "eval/compare.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>
#include <stb_image.h>

namespace penumbra {
namespace {

double percentile(std::vector<double> v, double q) {
    if (v.empty()) return 0.0;
    const size_t k = std::min(v.size() - 1, size_t(q * double(v.size() - 1) + 0.5));
    std::nth_element(v.begin(), v.begin() + k, v.end());
    return v[k];
}

std::vector<double> luminanceOf(const ImageF& img) {
    std::vector<double> y(size_t(img.width) * img.height);
    for (size_t i = 0; i < y.size(); ++i) y[i] = luminance(&img.rgba[i * 4]);
    return y;
}

// Separable Gaussian blur with the window cut at the border and renormalised by the weights left.
std::vector<double> gaussianBlur(const std::vector<double>& in, uint32_t w, uint32_t h) {
    constexpr int r = kSsimWindow / 2;
    std::array<double, kSsimWindow> k{};
    for (int i = -r; i <= r; ++i) k[i + r] = std::exp(-0.5 * i * i / (kSsimSigma * kSsimSigma));
    std::vector<double> tmp(in.size()), out(in.size());
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            double s = 0.0, ws = 0.0;
            for (int i = -r; i <= r; ++i) {
                const int xx = int(x) + i;
                if (xx < 0 || xx >= int(w)) continue;
                s += k[i + r] * in[size_t(y) * w + xx], ws += k[i + r];
            }
            tmp[size_t(y) * w + x] = s / ws;
        }
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            double s = 0.0, ws = 0.0;
            for (int i = -r; i <= r; ++i) {
                const int yy = int(y) + i;
                if (yy < 0 || yy >= int(h)) continue;
                s += k[i + r] * tmp[size_t(yy) * w + x], ws += k[i + r];
            }
            out[size_t(y) * w + x] = s / ws;
        }
    return out;
}

// Mean SSIM (Wang, Bovik, Sheikh, Simoncelli 2004, eq. 13) of luminance over the compared pixels.
double meanSsim(const ImageF& a, const ImageF& b, const std::vector<uint8_t>& mask, double range) {
    const uint32_t w = a.width, h = a.height;
    const std::vector<double> ya = luminanceOf(a), yb = luminanceOf(b);
    std::vector<double> aa(ya.size()), bb(ya.size()), ab(ya.size());
    for (size_t i = 0; i < ya.size(); ++i) aa[i] = ya[i] * ya[i], bb[i] = yb[i] * yb[i], ab[i] = ya[i] * yb[i];
    const std::vector<double> ma = gaussianBlur(ya, w, h), mb = gaussianBlur(yb, w, h);
    const std::vector<double> saa = gaussianBlur(aa, w, h), sbb = gaussianBlur(bb, w, h), sab = gaussianBlur(ab, w, h);
    const double c1 = std::pow(0.01 * range, 2), c2 = std::pow(0.03 * range, 2);
    double sum = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < ya.size(); ++i) {
        if (!mask.empty() && !mask[i]) continue;
        const double va = saa[i] - ma[i] * ma[i], vb = sbb[i] - mb[i] * mb[i], cov = sab[i] - ma[i] * mb[i];
        sum += (2.0 * ma[i] * mb[i] + c1) * (2.0 * cov + c2) /
               ((ma[i] * ma[i] + mb[i] * mb[i] + c1) * (va + vb + c2));
        ++n;
    }
    return n ? sum / double(n) : 1.0;
}

void checkSizes(const ImageF& a, const ImageF& b, const std::vector<uint8_t>& mask) {
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument(
            fmt::format("image sizes differ: {}x{} and {}x{}", a.width, a.height, b.width, b.height));
    if (!mask.empty() && mask.size() != size_t(a.width) * a.height)
        throw std::invalid_argument("the mask's size differs from the images'");
}

// A five-stop ramp close to matplotlib's "inferno" (perceptually ordered, readable in grey).
std::array<uint8_t, 3> ramp(double t) {
    static const double stops[6][3] = {{0, 0, 4},       {40, 11, 84},    {101, 21, 110},
                                       {188, 55, 84},   {249, 142, 9},   {252, 255, 164}};
    t = std::clamp(t, 0.0, 1.0) * 5.0;
    const int i = std::min(int(t), 4);
    const double f = t - i;
    std::array<uint8_t, 3> c{};
    for (int k = 0; k < 3; ++k) c[k] = uint8_t(std::lround(stops[i][k] + f * (stops[i + 1][k] - stops[i][k])));
    return c;
}

}  // namespace

double luminance(const float* rgb) { return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]; }

ImageMetrics compareImages(const ImageF& a, const ImageF& b, const std::vector<uint8_t>& mask) {
    checkSizes(a, b, mask);
    ImageMetrics m;
    double sumAbs = 0.0, sumSq = 0.0, sumRefAbs = 0.0, sumRefSq = 0.0, sumDiff = 0.0;
    std::vector<double> refLum;
    for (size_t i = 0; i < size_t(a.width) * a.height; ++i) {
        if (!mask.empty() && !mask[i]) continue;
        ++m.pixels;
        refLum.push_back(luminance(&b.rgba[i * 4]));
        double pixelMax = 0.0;
        for (int c = 0; c < 3; ++c) {
            const double va = a.rgba[i * 4 + c], vb = b.rgba[i * 4 + c], d = va - vb;
            sumAbs += std::abs(d), sumSq += d * d, sumDiff += d;
            sumRefAbs += std::abs(vb), sumRefSq += vb * vb;
            pixelMax = std::max(pixelMax, std::abs(d));
        }
        m.maxError = std::max(m.maxError, pixelMax);
        m.differing += pixelMax > kDifferingError;
    }
    if (m.pixels == 0) throw std::invalid_argument("the mask selects no pixel");
    const double count = 3.0 * double(m.pixels);
    auto ratio = [](double num, double den) {
        return den > 0.0 ? num / den : num > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
    };
    m.rmse = std::sqrt(sumSq / count);
    m.relL1 = ratio(sumAbs, sumRefAbs);
    m.relL2 = std::sqrt(ratio(sumSq, sumRefSq));
    m.meanBias = sumDiff / count;
    m.refMean = sumRefAbs / count;
    // A black reference has no range: fall back to 1 so that the constants stay positive.
    m.ssimRange = percentile(refLum, 0.99);
    if (!(m.ssimRange > 0.0)) m.ssimRange = 1.0;
    m.ssim = meanSsim(a, b, mask, m.ssimRange);
    return m;
}

std::vector<uint8_t> errorHeatMap(const ImageF& a, const ImageF& b, const std::vector<uint8_t>& mask, double& scale) {
    checkSizes(a, b, mask);
    const size_t n = size_t(a.width) * a.height;
    std::vector<double> err(n);
    std::vector<double> compared;
    for (size_t i = 0; i < n; ++i) {
        err[i] = std::abs(luminance(&a.rgba[i * 4]) - luminance(&b.rgba[i * 4]));
        if (mask.empty() || mask[i]) compared.push_back(err[i]);
    }
    if (!(scale > 0.0)) scale = percentile(compared, 0.99);
    if (!(scale > 0.0)) scale = std::max(*std::max_element(err.begin(), err.end()), 1e-30);
    std::vector<uint8_t> out(n * 4, 255);
    for (size_t i = 0; i < n; ++i) {
        const std::array<uint8_t, 3> c = !mask.empty() && !mask[i] ? std::array<uint8_t, 3>{96, 96, 96}
                                                                    : ramp(err[i] / scale);
        std::copy(c.begin(), c.end(), out.begin() + i * 4);
    }
    return out;
}

ImageF readExrChecked(const std::string& path, const std::string& what) {
    if (!std::ifstream(path)) throw std::invalid_argument(fmt::format("{} {}: no such file", what, path));
    char magic[4] = {};
    std::ifstream(path, std::ios::binary).read(magic, 4);
    // OpenEXR files start with 0x76 0x2f 0x31 0x01.
    const uint8_t exr[4] = {0x76, 0x2f, 0x31, 0x01};
    if (std::memcmp(magic, exr, 4) != 0)
        throw std::invalid_argument(fmt::format("{} {}: not an OpenEXR file", what, path));
    return readExr(path);
}

ImageF readExrSized(const std::string& path, const std::string& what, uint32_t width, uint32_t height) {
    ImageF image = readExrChecked(path, what);
    if (image.width != width || image.height != height)
        throw std::invalid_argument(fmt::format("{} {}: the image is {}x{}, expected {}x{}", what, path, image.width,
                                                image.height, width, height));
    return image;
}

std::vector<uint8_t> loadMask(const std::string& path, const std::string& what, uint32_t width, uint32_t height) {
    if (!std::ifstream(path)) throw std::invalid_argument(fmt::format("{} {}: no such file", what, path));
    ImageF img;
    if (fileExtension(path) == ".exr") {
        img = readExrChecked(path, what);
    } else {
        int w = 0, h = 0, channels = 0;
        float* data = stbi_loadf(path.c_str(), &w, &h, &channels, 4);
        if (!data) throw std::invalid_argument(fmt::format("{} {}: cannot read the image ({})", what, path,
                                                           stbi_failure_reason()));
        img = {uint32_t(w), uint32_t(h), std::vector<float>(data, data + size_t(w) * h * 4)};
        stbi_image_free(data);
    }
    if (img.width != width || img.height != height)
        throw std::invalid_argument(
            fmt::format("{} {}: {}x{}, the images are {}x{}", what, path, img.width, img.height, width, height));
    std::vector<uint8_t> mask(size_t(width) * height);
    for (size_t i = 0; i < mask.size(); ++i)
        mask[i] = img.rgba[i * 4] != 0.0f || img.rgba[i * 4 + 1] != 0.0f || img.rgba[i * 4 + 2] != 0.0f;
    return mask;
}

std::vector<uint8_t> toneMap(const ImageF& image, float exposure) {
    std::vector<uint8_t> out(size_t(image.width) * image.height * 4, 255);
    for (size_t i = 0; i < size_t(image.width) * image.height; ++i)
        for (int c = 0; c < 3; ++c) {
            const double x = std::max(0.0, double(image.rgba[i * 4 + c]) * exposure);
            double v = std::clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
            v = v <= 0.0031308 ? v * 12.92 : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
            out[i * 4 + c] = uint8_t(std::lround(v * 255.0));
        }
    return out;
}

}  // namespace penumbra
