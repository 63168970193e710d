#include "k40t_driver/video/rtsp_probe.h"

#include <gst/gst.h>
#include <gst/rtsp/rtsp.h>

#include <cmath>
#include <memory>

namespace k40t::video {

namespace {

struct UrlDeleter {
  void operator()(GstRTSPUrl* url) const { gst_rtsp_url_free(url); }
};
struct ConnectionDeleter {
  void operator()(GstRTSPConnection* connection) const { gst_rtsp_connection_free(connection); }
};

Status failed(const std::string& url, const std::string& what, GstRTSPResult result) {
  char* text = gst_rtsp_strresult(result);
  const std::string message = "RTSP server " + url + " " + what + ": " + text;
  g_free(text);
  return Status::fail(message);
}

}  // namespace

Status probe_rtsp(const std::string& url, double timeout_s) {
  if (!gst_is_initialized()) gst_init(nullptr, nullptr);
  GstRTSPUrl* parsed_raw = nullptr;
  if (gst_rtsp_url_parse(url.c_str(), &parsed_raw) != GST_RTSP_OK || !parsed_raw) {
    return Status::fail("video URL '" + url + "' is not a valid RTSP URL");
  }
  std::unique_ptr<GstRTSPUrl, UrlDeleter> parsed(parsed_raw);
  GstRTSPConnection* connection_raw = nullptr;
  GstRTSPResult result = gst_rtsp_connection_create(parsed.get(), &connection_raw);
  if (result != GST_RTSP_OK) return failed(url, "cannot be reached", result);
  std::unique_ptr<GstRTSPConnection, ConnectionDeleter> connection(connection_raw);

  const gint64 timeout_us = std::llround(timeout_s * 1e6);
  result = gst_rtsp_connection_connect_usec(connection.get(), timeout_us);
  if (result != GST_RTSP_OK) return failed(url, "does not accept connections", result);

  GstRTSPMessage request = {};
  gst_rtsp_message_init_request(&request, GST_RTSP_OPTIONS, url.c_str());
  gst_rtsp_message_add_header(&request, GST_RTSP_HDR_CSEQ, "1");
  result = gst_rtsp_connection_send_usec(connection.get(), &request, timeout_us);
  gst_rtsp_message_unset(&request);
  if (result != GST_RTSP_OK) return failed(url, "cannot be sent a request", result);

  GstRTSPMessage response = {};
  result = gst_rtsp_connection_receive_usec(connection.get(), &response, timeout_us);
  const bool answered = result == GST_RTSP_OK && response.type == GST_RTSP_MESSAGE_RESPONSE;
  const GstRTSPStatusCode code = answered ? response.type_data.response.code : GST_RTSP_STS_INVALID;
  gst_rtsp_message_unset(&response);
  gst_rtsp_connection_close(connection.get());
  if (!answered) return failed(url, "does not answer OPTIONS", result);
  if (code != GST_RTSP_STS_OK) {
    return Status::fail("RTSP server " + url + " answers OPTIONS with " + std::to_string(code) +
                        " " + gst_rtsp_status_as_text(code));
  }
  return Status::ok();
}

}  // namespace k40t::video
