// Image comparison for `penumbra compare` and `penumbra eval`: error metrics of a test image A
// against a reference B (linear RGB, e.g. EXR radiance), SSIM on luminance, an error heat map.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "io/image_io.h"

namespace penumbra {

// Over the compared pixels (all, or the mask's) and the three colour channels, d = A - B:
struct ImageMetrics {
    size_t pixels = 0;       // compared pixels
    double rmse = 0.0;       // sqrt(mean d^2)
    double relL1 = 0.0;      // sum |d| / sum |B|  (0 when both are 0, infinity when only B is)
    double relL2 = 0.0;      // sqrt(sum d^2 / sum B^2)
    double meanBias = 0.0;   // mean d: > 0 when A is brighter on average
    double refMean = 0.0;    // mean B (meanBias / refMean is the relative bias)
    double maxError = 0.0;   // max |d|
    size_t differing = 0;    // pixels with some channel's |d| > kDifferingError (e.g. a shadow AOV's flips)
    double ssim = 1.0;       // mean SSIM of the luminance over compared pixels (kSsimWindow, kSsimSigma)
    double ssimRange = 0.0;  // the dynamic range L of SSIM's constants (see compareImages)
};

constexpr double kDifferingError = 1e-3;
constexpr int kSsimWindow = 11;      // Gaussian window side (Wang et al. 2004)
constexpr double kSsimSigma = 1.5;   // and its standard deviation, pixels

double luminance(const float* rgb);  // Rec. 709 weights

// Throws std::invalid_argument when the sizes differ or the mask selects no pixel. `mask`: empty,
// or one byte per pixel, non-zero = compared. SSIM uses C1 = (0.01 L)^2, C2 = (0.03 L)^2 with L the
// 99th percentile of B's luminance over the compared pixels (HDR images have no fixed range; a
// percentile is not moved by a few bright pixels); the window is cut at the image border and
// renormalised.
ImageMetrics compareImages(const ImageF& a, const ImageF& b, const std::vector<uint8_t>& mask = {});

// RGBA8 heat map of |Y(A) - Y(B)| (luminance): black 0 .. dark red .. orange .. pale yellow at
// `scale` and above; pixels outside the mask grey. scale <= 0: the 99th percentile of the
// compared errors, returned in `scale`.
std::vector<uint8_t> errorHeatMap(const ImageF& a, const ImageF& b, const std::vector<uint8_t>& mask, double& scale);

// A mask image (EXR or PNG) of width x height: 1 where any of R, G, B is non-zero.
std::vector<uint8_t> loadMask(const std::string& path, const std::string& what, uint32_t width, uint32_t height);

// Reads an EXR that must exist and be an EXR: one clear line otherwise ("A.exr: not an EXR file").
ImageF readExrChecked(const std::string& path, const std::string& what);
// readExrChecked, and the image must be width x height: the error names the file and both sizes.
ImageF readExrSized(const std::string& path, const std::string& what, uint32_t width, uint32_t height);

// The renderer's PNG tone mapping on the CPU: exposure, ACES fit (Narkowicz 2015), sRGB.
std::vector<uint8_t> toneMap(const ImageF& image, float exposure);

}  // namespace penumbra
