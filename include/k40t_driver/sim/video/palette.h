// The thermal camera's 20 colour palettes (0x000106, codes 1..20), approximated: each is a
// 256-entry lookup table from the normalised temperature (0 coldest, 255 hottest in view) to a
// BGR colour, built from a few colour stops that give the palette's documented character
// (white hot, black hot, rainbow, iron red, ...). The real pod's exact tables are not published.
#pragma once

#include <string>

#include <opencv2/core.hpp>

#include "k40t_driver/protocol/result.h"

namespace k40t::sim::video {

constexpr int kFirstPalette = 1;
constexpr int kLastPalette = 20;

// The palette's name: the protocol's to_string(Palette), as cfg/setting_enums.txt spells it
// ("white_hot", "iron_red", ...).
Result<std::string> palette_name(int palette);

// A 1 x 256 CV_8UC3 table (BGR) for cv::LUT; an error naming the code when it is not 1..20.
Result<cv::Mat> palette_table(int palette);

}  // namespace k40t::sim::video
