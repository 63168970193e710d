// The repository stands alone: every citation of its docs ("docs/protocol/decisions.md#a2" in a
// comment, "[video](video.md#split-screen)" in a doc) names a file and an anchor that exist, and
// nothing cites the vendor folder or the decision notes the docs were written from.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

const fs::path kRoot = fs::path(K40T_TEST_DATA_DIR).parent_path().parent_path();

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// GitHub's heading anchor: lower case, punctuation dropped (but '-' and '_'), spaces to '-'.
std::string heading_anchor(const std::string& heading) {
  std::string anchor;
  for (unsigned char c : heading) {
    if (std::isalnum(c) || c == '-' || c == '_' || c >= 0x80) {
      anchor += static_cast<char>(std::tolower(c));
    } else if (c == ' ') {
      anchor += '-';
    }
  }
  return anchor;
}

std::set<std::string> anchors_of(const fs::path& doc) {
  static std::map<fs::path, std::set<std::string>> cache;
  auto found = cache.find(doc);
  if (found != cache.end()) return found->second;
  std::set<std::string> anchors;
  const std::string text = read_text(doc);
  static const std::regex heading(R"(^#+ +(.*?) *$)", std::regex::multiline);
  static const std::regex explicit_id(R"re(<a (?:id|name)="([^"]+)")re");
  for (std::sregex_iterator m(text.begin(), text.end(), heading), end; m != end; ++m)
    anchors.insert(heading_anchor((*m)[1]));
  for (std::sregex_iterator m(text.begin(), text.end(), explicit_id), end; m != end; ++m)
    anchors.insert((*m)[1]);
  return cache[doc] = anchors;
}

bool is_text_source(const fs::path& path) {
  static const std::set<std::string> kExtensions = {
      ".h",    ".cpp", ".py", ".md",  ".cfg",   ".msg",   ".srv",  ".action", ".launch",
      ".test", ".xml", ".sh", ".txt", ".cmake", ".xacro", ".yaml", ".rst"};
  return kExtensions.count(path.extension().string()) > 0 || path.filename() == "run";
}

std::vector<fs::path> repository_files() {
  std::vector<fs::path> files;
  for (const char* top :
       {"include", "src", "test", "tools", "bench", "fuzz", "cfg", "msg", "srv", "action", "launch",
        "scripts", "docs", "urdf", "config", "cmake", ".ci"}) {
    if (!fs::is_directory(kRoot / top)) continue;
    for (const auto& entry : fs::recursive_directory_iterator(kRoot / top)) {
      if (entry.is_regular_file() && is_text_source(entry.path())) files.push_back(entry.path());
    }
  }
  for (const char* file : {"README.md", "CHANGELOG.rst", "CMakeLists.txt", "package.xml"})
    if (fs::exists(kRoot / file)) files.push_back(kRoot / file);
  return files;
}

struct Citation {
  fs::path file;  // where it is written
  fs::path doc;   // the document it names
  std::string anchor;
};

std::vector<Citation> citations_in(const fs::path& file) {
  std::vector<Citation> citations;
  const std::string text = read_text(file);
  // "docs/<path>.md#anchor", anywhere (code comments, docs, scripts).
  static const std::regex from_root(R"(\bdocs/([A-Za-z0-9_/.-]+\.md)#([A-Za-z0-9_-]+))");
  for (std::sregex_iterator m(text.begin(), text.end(), from_root), end; m != end; ++m)
    citations.push_back({file, kRoot / "docs" / (*m)[1].str(), (*m)[2]});
  // A Markdown link with an anchor, relative to the document it is in.
  if (file.extension() == ".md") {
    static const std::regex link(R"(\]\(([A-Za-z0-9_/.-]*\.md)?#([A-Za-z0-9_-]+)\))");
    for (std::sregex_iterator m(text.begin(), text.end(), link), end; m != end; ++m) {
      const fs::path target =
          (*m)[1].matched && (*m)[1].length() > 0 ? file.parent_path() / (*m)[1].str() : file;
      citations.push_back({file, target, (*m)[2]});
    }
  }
  return citations;
}

std::string in_repository(const fs::path& path) {
  return fs::relative(path, kRoot).string();
}

TEST(DocsCitations, EveryCitedDocumentAndAnchorExists) {
  size_t checked = 0;
  for (const fs::path& file : repository_files()) {
    for (const Citation& citation : citations_in(file)) {
      ++checked;
      const fs::path doc = citation.doc.lexically_normal();
      if (!fs::exists(doc)) {
        ADD_FAILURE() << in_repository(citation.file) << " cites " << in_repository(doc) << "#"
                      << citation.anchor << ": no such file";
        continue;
      }
      EXPECT_TRUE(anchors_of(doc).count(citation.anchor))
          << in_repository(citation.file) << " cites " << in_repository(doc) << "#"
          << citation.anchor << ": the document has no such heading or <a id>";
    }
  }
  // The code cites the decisions by anchor in many places; none found means the scan is broken.
  EXPECT_GT(checked, 50u);
}

TEST(DocsCitations, NothingCitesAFileOutsideTheRepository) {
  // The vendor documents and the notes they were read with live outside the repository; what
  // they decide is written in docs/protocol/ (one anchor per decision).
  static const std::regex outside(R"((\.\./shared/|shared/spec/|\bNOTES\.md\b|\bNOTES A[0-9]+))");
  const fs::path self = fs::path(__FILE__).filename();
  for (const fs::path& file : repository_files()) {
    if (file.filename() == self) continue;
    const std::string text = read_text(file);
    std::smatch m;
    EXPECT_FALSE(std::regex_search(text, m, outside))
        << in_repository(file) << " cites \"" << m.str() << "\", a file outside the repository";
  }
}

TEST(DocsCitations, HeadingAnchorsFollowGitHubsRule) {
  EXPECT_EQ(heading_anchor("A2: byte order of ACK fields (2.1 note)"),
            "a2-byte-order-of-ack-fields-21-note");
  EXPECT_EQ(heading_anchor("dynamic_reconfigure (`cfg/K40t.cfg`, server `/k40t/driver`)"),
            "dynamic_reconfigure-cfgk40tcfg-server-k40tdriver");
}

}  // namespace
