#include "frame_export.h"

#include <sys/stat.h>

#include <cctype>
#include <cerrno>
#include <cstring>
#include <vector>

#include "frame_text.h"  // tools/k40t: the k40t tool's frame JSON
#include "input.h"
#include "json_sink.h"
#include "k40t_driver/protocol/catalogue.h"

namespace k40t::driver {

namespace {

using FilePtr = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

Result<FilePtr> open_file(const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "w");
  if (file == nullptr)
    return Result<FilePtr>::fail("cannot write " + path + ": " + std::strerror(errno));
  return FilePtr(file, &std::fclose);
}

Status finish_file(std::FILE* file, const std::string& path) {
  if (std::fflush(file) != 0 || std::ferror(file))
    return Status::fail("error writing " + path + ": " + std::strerror(errno));
  return Status::ok();
}

class JsonLinesExport : public FrameExport {
 public:
  JsonLinesExport(FilePtr file, std::string path)
      : file_(std::move(file)), path_(std::move(path)) {}
  void write(const ExportedFrame& f, const protocol::CodecOptions& codec) override {
    tool::JsonWriter out;
    out.begin_object();
    out.member("bag", f.bag);
    out.member("topic", f.topic);
    out.key("stamp_ns");
    out.integer(f.stamp_ns);
    out.key("frame");
    out.raw(tool::frame_json(f.frame, f.index, codec));
    out.end_object();
    std::fputs(out.text().c_str(), file_.get());
    std::fputc('\n', file_.get());
  }
  Status finish() override { return finish_file(file_.get(), path_); }

 private:
  FilePtr file_;
  std::string path_;
};

std::string csv_quoted(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

// A message's fields as CSV columns (names) and cells (values), in declaration order; reals with
// every digit.
class CsvRowSink : public tool::FieldTextSink {
 public:
  CsvRowSink() : FieldTextSink("%.17g") {}
  void text(const char* name, const std::string& value) override { add(name, csv_quoted(value)); }
  void enumeration(const char* name, int64_t code, const char* label) override {
    add(name, std::to_string(code));
    add(std::string(name) + "_label", label ? csv_quoted(label) : "");
  }
  void bytes(const char* name, const uint8_t* data, size_t size) override {
    add(name, tool::to_hex(data, size));
  }
  std::string names, values;

 private:
  void add(const std::string& name, const std::string& value) override {
    names += "," + name;
    values += "," + value;
  }
};

// "0x000002_gimbal_attitude"
std::string file_stem(const protocol::MessageInfo& info) {
  std::string stem = tool::id_text(info.id) + "_";
  for (const char* c = info.name; *c; ++c) {
    const bool keep = std::isalnum(static_cast<unsigned char>(*c));
    if (keep)
      stem += static_cast<char>(std::tolower(static_cast<unsigned char>(*c)));
    else if (stem.back() != '_')
      stem += '_';
  }
  while (stem.back() == '_') stem.pop_back();
  return stem;
}

class CsvExport : public FrameExport {
 public:
  explicit CsvExport(std::string directory) : directory_(std::move(directory)) {}
  void write(const ExportedFrame& f, const protocol::CodecOptions& codec) override {
    const protocol::MessageInfo* info = protocol::find_message(f.frame.header.message_id);
    if (info == nullptr) return;
    CsvRowSink row;
    if (!info->describe(f.frame.payload, f.frame.payload_size, codec, row)) return;
    auto it = files_.find(info->id);
    if (it == files_.end()) {
      const std::string path = directory_ + "/" + file_stem(*info) + ".csv";
      Result<FilePtr> file = open_file(path);
      if (!file) {
        if (error_.empty()) error_ = file.error();
        return;
      }
      it = files_.emplace(info->id, Output{std::move(file.value()), path}).first;
      std::fprintf(it->second.file.get(), "bag,topic,stamp_ns,src,dst,seq%s\n", row.names.c_str());
    }
    std::fprintf(it->second.file.get(), "%s,%s,%lld,%s,%s,%u%s\n", csv_quoted(f.bag).c_str(),
                 f.topic.c_str(), static_cast<long long>(f.stamp_ns),
                 tool::address_text(f.frame.header.source).c_str(),
                 tool::address_text(f.frame.header.destination).c_str(),
                 static_cast<unsigned>(f.frame.header.sequence), row.values.c_str());
  }
  Status finish() override {
    if (!error_.empty()) return Status::fail(error_);
    for (auto& [id, output] : files_) {
      const Status done = finish_file(output.file.get(), output.path);
      if (!done) return done;
    }
    return Status::ok();
  }

 private:
  struct Output {
    FilePtr file;
    std::string path;
  };
  std::string directory_;
  std::map<protocol::MessageId, Output> files_;
  std::string error_;
};

}  // namespace

Result<std::unique_ptr<FrameExport>> open_jsonl_export(const std::string& path) {
  Result<FilePtr> file = open_file(path);
  if (!file) return Result<std::unique_ptr<FrameExport>>::fail(file.error());
  return std::unique_ptr<FrameExport>(new JsonLinesExport(std::move(file.value()), path));
}

Result<std::unique_ptr<FrameExport>> open_csv_export(const std::string& directory) {
  if (::mkdir(directory.c_str(), 0777) != 0 && errno != EEXIST)
    return Result<std::unique_ptr<FrameExport>>::fail("cannot create " + directory + ": " +
                                                      std::strerror(errno));
  return std::unique_ptr<FrameExport>(new CsvExport(directory));
}

}  // namespace k40t::driver
