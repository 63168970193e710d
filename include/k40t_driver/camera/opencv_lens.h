// OpenCV's lens distortion (calib3d) in a library of its own, libk40t_opencv_lens.so, opened on
// the first pixel that needs it: calib3d and what it brings (imgproc, features2d, flann, LAPACK,
// GL, X11) cost a process that links them ~4.8 MB of resident memory from its start, and most
// drivers never locate a pixel. pixel_ray.h is the interface; this is its plumbing.
#pragma once

#include "k40t_driver/camera/pixel_ray.h"
#include "k40t_driver/protocol/result.h"

namespace k40t::camera {

enum class LensModel { kNone, kPinholeFamily, kFisheye };

// The library's functions (same compiler and CameraModel on both sides: they are built together).
struct OpenCvLens {
  // The undistorted normalised point (x, y) of pixel (u, v).
  std::array<double, 2> (*undistort)(const CameraModel& camera, LensModel model, double u,
                                     double v);
  // Where the ray (x, y, z), z > 0, appears in the distorted image.
  std::array<double, 2> (*project)(const CameraModel& camera, LensModel model,
                                   const std::array<double, 3>& ray);
};

// The library's file name, and the one symbol it exports.
constexpr const char* kOpenCvLensLibrary = "libk40t_opencv_lens.so";
constexpr const char* kOpenCvLensSymbol = "k40t_opencv_lens";

// The functions, the library opened on the first call (thread-safe; it stays loaded); why not
// when it cannot be found or opened. Looked for beside the program's own code (the devel or
// install space's lib/, beside a library that has this code; the build's bin/, beside a program),
// then on the library path.
Result<const OpenCvLens*> opencv_lens();

}  // namespace k40t::camera
