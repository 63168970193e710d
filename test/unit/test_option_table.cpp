// The simulators' shared command-line parser (sim/option_table.h).
#include <gtest/gtest.h>

#include "k40t_driver/sim/option_table.h"

namespace k40t::sim {
namespace {

struct Toy {
  std::string link;
  bool verbose = false;
};

const std::vector<OptionSpec<Toy>>& toy_table() {
  static const std::vector<OptionSpec<Toy>> kTable = {
      {"--link", "URL", "where",
       [](Toy& t, const std::string&, const std::string& v) {
         t.link = v;
         return Status::ok();
       }},
      {"--verbose", nullptr, "talk",
       [](Toy& t, const std::string&, const std::string&) {
         t.verbose = true;
         return Status::ok();
       }},
  };
  return kTable;
}

TEST(OptionTable, ValuesInlineOrSeparateFlagsAndRosArguments) {
  Toy toy;
  ASSERT_TRUE(parse_option_table(toy_table(), {"__name:=sim", "--link=pty:/a", "--verbose"}, toy));
  EXPECT_EQ(toy.link, "pty:/a");
  EXPECT_TRUE(toy.verbose);
  ASSERT_TRUE(parse_option_table(toy_table(), {"--link", "udp://x:1"}, toy));
  EXPECT_EQ(toy.link, "udp://x:1");
}

TEST(OptionTable, ErrorsNameTheOption) {
  Toy toy;
  const Status unknown = parse_option_table(toy_table(), {"--lnk", "x"}, toy);
  EXPECT_NE(unknown.message().find("unknown argument '--lnk'"), std::string::npos);
  const Status missing = parse_option_table(toy_table(), {"--link"}, toy);
  EXPECT_NE(missing.message().find("--link: missing URL"), std::string::npos);
  const Status flag = parse_option_table(toy_table(), {"--verbose=1"}, toy);
  EXPECT_NE(flag.message().find("--verbose: takes no value"), std::string::npos);
}

TEST(OptionTable, UsageWrapsHelpInOneColumn) {
  const std::string text = format_option("--link", "URL", std::string(150, 'x').c_str());
  EXPECT_EQ(text.rfind("  --link URL", 0), 0u);
  EXPECT_EQ(text.find("x"), 30u);  // the help column
}

}  // namespace
}  // namespace k40t::sim
