// gst_parse_launch() with its error turned into a message, for the video code's pipelines
// (app_pipeline, container_writer, access_unit_source). GStreamer types: only for src/video/.
#pragma once

#include <gst/gst.h>

#include <string>

#include "k40t_driver/protocol/result.h"

namespace k40t::video {

// The pipeline (owned by the caller: gst_object_unref), or "cannot build the WHAT pipeline: ...".
Result<GstElement*> launch_pipeline(const std::string& description, const std::string& what);

}  // namespace k40t::video
