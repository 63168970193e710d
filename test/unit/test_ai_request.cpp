// ai/recognition's 0x000319 (section 3.2.4.23): unused class slots repeat the last class instead
// of going out as 0, which is a real class in most label files ("person").
#include <gtest/gtest.h>

#include "k40t_driver/operations/ai_request.h"

namespace k40t::operations {
namespace {

namespace p = protocol;

TEST(AiRecognitionRequest, UnusedSlotsRepeatTheLastClass) {
  const Result<p::AiRecognitionRequest> r = ai_recognition_request(true, 3, {2, 7});
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r->recognition, p::FeatureSwitch::kOn);
  EXPECT_EQ(r->model, 3);
  // Byte 1 switch 0x01, byte 2 model, bytes 3-12 the classes (section 3.2.4.23).
  const std::vector<uint8_t> expected = {0x01, 0x03, 2, 7, 7, 7, 7, 7, 7, 7, 7, 7};
  const Result<p::Payload> bytes = p::encode_payload(r.value());
  ASSERT_TRUE(bytes);
  EXPECT_EQ(std::vector<uint8_t>(bytes->data(), bytes->data() + bytes->size), expected);
}

TEST(AiRecognitionRequest, OnNeedsAClassOffIgnoresThem) {
  const Result<p::AiRecognitionRequest> none = ai_recognition_request(true, 0, {});
  ASSERT_FALSE(none);
  EXPECT_NE(none.error().find("field 'classes' must hold 1..10 class ids"), std::string::npos)
      << none.error();
  const Result<p::AiRecognitionRequest> off = ai_recognition_request(false, 0, {});
  ASSERT_TRUE(off) << off.error();
  EXPECT_EQ(off->recognition, p::FeatureSwitch::kOff);
  const Result<p::AiRecognitionRequest> eleven =
      ai_recognition_request(true, 0, std::vector<uint8_t>(11, 1));
  ASSERT_FALSE(eleven);
  EXPECT_NE(eleven.error().find("at most 10"), std::string::npos);
}

}  // namespace
}  // namespace k40t::operations
