// k40t_bag, run as `k40t bag`: decodes recorded flights offline (bag_decoder.h). Needs the ROS
// build (rosbag's storage library), hence its own program, which the ROS-free `k40t` runs.
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "command.h"  // tools/k40t: argument parsing and help shared with the other subcommands
#include "k40t_driver/ros/bag/bag_decoder.h"
#include "k40t_driver/ros/bag/video_export.h"
#include "k40t_driver/ros/bag/yaml_params.h"
#include "progress_bar.h"

namespace k40t::tool {
namespace {

using driver::BagDecodeOptions;
using driver::BagDecodeSummary;

// flight.bag -> <dir or flight's dir>/flight.decoded.bag
std::string output_path(const std::string& input, const std::string& out_dir) {
  const size_t slash = input.rfind('/');
  const std::string dir = slash == std::string::npos ? "." : input.substr(0, slash);
  std::string name = slash == std::string::npos ? input : input.substr(slash + 1);
  if (name.size() > 4 && name.compare(name.size() - 4, 4, ".bag") == 0)
    name.resize(name.size() - 4);
  return (out_dir.empty() ? dir : out_dir) + "/" + name + ".decoded.bag";
}

Result<driver::RosPodConfig> read_config(const ParsedArgs& args) {
  XmlRpc::XmlRpcValue params;
  params.begin();  // no file: an empty struct, every parameter at its default
  if (args.has("--config")) {
    Result<XmlRpc::XmlRpcValue> loaded = driver::load_yaml_params(args.options.at("--config"));
    if (!loaded) return Result<driver::RosPodConfig>::fail(loaded.error());
    params = loaded.value();
  }
  // The open readings on top (docs/protocol/decisions.md#conventions), as k40t.launch loads them.
  if (args.has("--conventions")) {
    Result<XmlRpc::XmlRpcValue> loaded = driver::load_yaml_params(args.options.at("--conventions"));
    if (!loaded) return Result<driver::RosPodConfig>::fail(loaded.error());
    for (auto& [name, value] : loaded.value()) params[name] = value;
  }
  driver::ParamReader reader(params, "~");
  return driver::read_params(reader);
}

// "pod_a_" (every pod) or "/pod_a=pod_a_,/pod_b=pod_b_" (by namespace).
Result<std::map<std::string, std::string>> parse_frame_prefixes(const std::string& text) {
  std::map<std::string, std::string> prefixes;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t comma = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, comma - start);
    const size_t equals = item.find('=');
    std::string ns = equals == std::string::npos ? "" : item.substr(0, equals);
    const std::string prefix = equals == std::string::npos ? item : item.substr(equals + 1);
    if (!ns.empty() && ns[0] != '/') ns = "/" + ns;
    while (ns.size() > 1 && ns.back() == '/') ns.pop_back();
    if (prefixes.count(ns))
      return Result<std::map<std::string, std::string>>::fail(
          "--frame-prefix names " + (ns.empty() ? std::string("every pod") : ns) + " twice");
    prefixes[ns] = prefix;
    start = comma + 1;
  }
  return prefixes;
}

// Decodes one bag into `output`; on failure the partial output is removed.
bool decode_one(const std::string& input, const std::string& output, BagDecodeOptions options) {
  if (output == input) {
    std::fprintf(stderr, "k40t bag: %s: the output would overwrite the input\n", input.c_str());
    return false;
  }
  Result<BagDecodeSummary> summary = Result<BagDecodeSummary>::fail("");
  try {
    rosbag::Bag out(output, rosbag::bagmode::Write);
    ProgressBar progress(input);
    options.progress = [&progress](double fraction) { progress.update(fraction); };
    summary = driver::decode_bag(input, out, options);
    out.close();
  } catch (const std::exception& e) {
    summary = Result<BagDecodeSummary>::fail(output + ": cannot write: " + e.what());
  }
  if (!summary) {
    std::fprintf(stderr, "k40t bag: %s\n", summary.error().c_str());
    ::unlink(output.c_str());
    return false;
  }
  std::string namespaces;
  for (const std::string& ns : summary->namespaces)
    namespaces += (namespaces.empty() ? "" : " ") + ns;
  std::fprintf(stderr, "k40t bag: %s -> %s: %llu frames (%llu rejected) -> %llu messages [%s]\n",
               input.c_str(), output.c_str(), static_cast<unsigned long long>(summary->rx_frames),
               static_cast<unsigned long long>(summary->bad_frames),
               static_cast<unsigned long long>(summary->messages_written), namespaces.c_str());
  return true;
}

// --video / --video-frames: the recorded passthrough topic out of one bag (video_export.h).
int run_video_export(const Command& self, const ParsedArgs& args) {
  if (args.positional.size() != 1)
    return usage_error(self, "--video and --video-frames take one input bag");
  driver::VideoExportOptions options;
  auto option = [&](const char* name) {
    return args.has(name) ? args.options.at(name) : std::string();
  };
  options.topic = option("--video-topic");
  options.video_file = option("--video");
  options.frames_dir = option("--video-frames");
  Result<driver::VideoExportSummary> summary = driver::export_video(args.positional[0], options);
  if (!summary) {
    std::fprintf(stderr, "k40t bag: %s\n", summary.error().c_str());
    return kExitFailed;
  }
  std::fprintf(stderr,
               "k40t bag: %s %s: %llu access units (%s, %.1f s) -> %llu in %s, %llu PNG frames "
               "in %s\n",
               args.positional[0].c_str(), summary->topic.c_str(),
               static_cast<unsigned long long>(summary->messages), summary->format.c_str(),
               summary->duration_s, static_cast<unsigned long long>(summary->written),
               options.video_file.empty() ? "-" : options.video_file.c_str(),
               static_cast<unsigned long long>(summary->frames),
               options.frames_dir.empty() ? "-" : options.frames_dir.c_str());
  return kExitOk;
}

int run_bag(const Command& self, const ParsedArgs& args) {
  if (args.positional.empty()) return usage_error(self, "give at least one bag");
  if (args.has("--video") || args.has("--video-frames")) return run_video_export(self, args);
  if (args.has("--video-topic"))
    return usage_error(self, "--video-topic goes with --video or --video-frames");
  if (args.has("--output") && args.positional.size() != 1)
    return usage_error(self, "--output takes one input bag; use --out-dir for several");
  Result<driver::RosPodConfig> config = read_config(args);
  if (!config) return usage_error(self, config.error());

  BagDecodeOptions options;
  options.config = config.value();
  if (args.has("--frame-prefix")) {
    auto prefixes = parse_frame_prefixes(args.options.at("--frame-prefix"));
    if (!prefixes) return usage_error(self, prefixes.error());
    options.frame_prefixes = prefixes.value();
  }
  std::vector<std::unique_ptr<driver::FrameExport>> exports;
  auto open_export = [&](const char* option, auto open) {
    if (!args.has(option)) return true;
    Result<std::unique_ptr<driver::FrameExport>> opened = open(args.options.at(option));
    if (!opened) {
      std::fprintf(stderr, "k40t bag: %s\n", opened.error().c_str());
      return false;
    }
    exports.push_back(std::move(opened.value()));
    options.exports.push_back(exports.back().get());
    return true;
  };
  if (!open_export("--jsonl", driver::open_jsonl_export) ||
      !open_export("--csv", driver::open_csv_export))
    return kExitFailed;

  const std::string out_dir = args.has("--out-dir") ? args.options.at("--out-dir") : "";
  if (!out_dir.empty() && ::mkdir(out_dir.c_str(), 0777) != 0 && errno != EEXIST) {
    std::fprintf(stderr, "k40t bag: cannot create %s: %s\n", out_dir.c_str(), std::strerror(errno));
    return kExitFailed;
  }
  size_t failed = 0;
  for (const std::string& input : args.positional) {
    const std::string output =
        args.has("--output") ? args.options.at("--output") : output_path(input, out_dir);
    if (!decode_one(input, output, options)) ++failed;  // and on with the next bag
  }
  for (const auto& e : exports) {
    const Status finished = e->finish();
    if (!finished) {
      std::fprintf(stderr, "k40t bag: %s\n", finished.message().c_str());
      ++failed;
    }
  }
  if (failed) {
    std::fprintf(stderr, "k40t bag: %zu of %zu bags failed\n", failed, args.positional.size());
  }
  return failed ? kExitFailed : kExitOk;
}

const Command& bag_command() {
  static const Command command{
      "bag",
      "bag BAG... [--out-dir DIR | --output FILE] [--config FILE] [--conventions FILE] "
      "[--jsonl FILE] [--csv DIR]\n"
      "       k40t bag BAG [--video FILE.mp4|.mkv] [--video-frames DIR] [--video-topic TOPIC]",
      "recorded flights -> bags of the decoded topics, at full speed (ROS build)",
      "Decodes the raw frames (<ns>/raw/rx, k40t_driver/Frame) of each BAG as replay.launch\n"
      "would, without a ROS master and at full speed, and writes every topic the driver\n"
      "publishes from them to BAG's name with .decoded.bag (next to BAG, or in --out-dir):\n"
      "same stamps, same header.seq, same content as a recording of the replay. Each raw/rx\n"
      "topic is one pod, decoded into its own namespace. /tf_static is written once, stamped\n"
      "with the first frame; diagnostics (wall-clock driven) are not decoded.\n"
      "A bag that cannot be read (no raw/rx, truncated, not a bag) is reported and skipped;\n"
      "the others are still decoded, and the exit code is 1.\n"
      "A progress bar is drawn on stderr when it is a terminal.\n"
      "With --video or --video-frames it exports the bag's passthrough video topic instead\n"
      "(k40t_driver/CompressedVideo, <ns>/image_raw/k40t_video): the access units muxed into\n"
      "an MP4 or MKV without re-encoding, and/or every frame as DIR/frame_NNNNNN.png with\n"
      "DIR/frames.csv (frame, stamp_ns, key_frame, file); both from the first key frame.",
      {{"--out-dir", "DIR", "write the decoded bags there (default: next to each input)"},
       {"--output", "FILE", "the decoded bag's path (one input only)"},
       {"--config", "FILE",
        "the driver's parameters as a YAML file (e.g. config/k40t.yaml, as the flight's "
        "driver had them: frame ids, offsets, byte orders); default: the built-in defaults"},
       {"--conventions", "FILE",
        "the open readings the pod followed (docs/protocol/decisions.md#conventions), a YAML "
        "file as k40t probe writes it; read after --config, whose values it overrides"},
       {"--frame-prefix", "[NS=]PREFIX,...",
        "frame and joint prefix the pods were recorded with, as replay.launch's frame_prefix: "
        "one for every pod, or per namespace (/pod_a=pod_a_,/pod_b=pod_b_)"},
       {"--jsonl", "FILE", "also write every raw frame (rx and tx), decoded, as JSON lines"},
       {"--csv", "DIR", "also write every raw frame's fields to DIR/<id>_<name>.csv"},
       {"--video", "FILE",
        "export the passthrough video to FILE (.mp4, .m4v, .mkv), no re-encoding"},
       {"--video-frames", "DIR", "export the passthrough video as PNG frames + frames.csv"},
       {"--video-topic", "TOPIC",
        "the video topic (default: the bag's only CompressedVideo topic)"}},
      &run_bag};
  return command;
}

}  // namespace
}  // namespace k40t::tool

int main(int argc, char** argv) {
  using namespace k40t::tool;
  const Command& self = bag_command();
  // `k40t bag ARGS` runs `k40t_bag ARGS`.
  k40t::Result<ParsedArgs> args =
      parse_args(std::vector<std::string>(argv + 1, argv + argc), self.options);
  if (!args) return usage_error(self, args.error());
  if (args->help) {
    print_command_help(self);
    return kExitOk;
  }
  return run_bag(self, args.value());
}
