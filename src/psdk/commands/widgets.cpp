#include "k40t_driver/psdk/commands/widgets.h"

#include "k40t_driver/codec/enum_names.h"
#include "k40t_driver/psdk/indexed_sink.h"

namespace k40t::psdk {

const char* to_string(WidgetType type) {
  return consecutive_name(type, 1,
                          {"button", "switch", "range_bar", "choose_list", "integer_input_box"});
}

// --- 3.2.5 ACK ----------------------------------------------------------------------------------

Status WidgetListDataAck::validate() const {
  Status s = first_failure(check_enum("type", type), check_int("index", index, 0, kMaxWidgets - 1),
                           codec::check_text("name", name, kWidgetNameSize - 1));
  if (!s) return s;
  if (type == WidgetType::kChooseList) {
    s = check_int("choose_item_count", choose_item_count, 1, kMaxChooseItems);
    for (size_t i = 0; s && i < choose_item_count; ++i) {
      s = codec::check_text("choose_items", choose_items[i], kChooseItemNameSize - 1);
    }
    return s;
  }
  if (choose_item_count != 0)
    return Status::fail("field 'choose_item_count' must be 0 unless the widget is a choose list");
  if (type == WidgetType::kIntegerInputBox) {
    return codec::check_text("input_box_suffix", input_box_suffix, kInputBoxSuffixSize - 1);
  }
  if (!input_box_suffix.empty()) {
    return Status::fail(
        "field 'input_box_suffix' must be empty unless the widget is an integer input box");
  }
  return Status::ok();
}

void WidgetListDataAck::encode(ByteWriter& w) const {
  w.u8(static_cast<uint8_t>(type));
  w.u8(index);
  w.text(name, kWidgetNameSize);
  if (type == WidgetType::kChooseList) {
    w.u8(choose_item_count);
    for (size_t i = 0; i < choose_item_count; ++i) w.text(choose_items[i], kChooseItemNameSize);
  } else if (type == WidgetType::kIntegerInputBox) {
    w.text(input_box_suffix, kInputBoxSuffixSize);
  }
}

Status WidgetListDataAck::decode(ByteReader& r) {
  type = static_cast<WidgetType>(r.u8());
  index = r.u8();
  name = r.text(kWidgetNameSize);
  if (type == WidgetType::kChooseList) {
    choose_item_count = r.u8();
    if (choose_item_count > kMaxChooseItems) {
      return Status::fail("choose list of " + std::to_string(choose_item_count) +
                          " items, at most 10 allowed");
    }
    for (size_t i = 0; i < choose_item_count; ++i) choose_items[i] = r.text(kChooseItemNameSize);
  } else if (type == WidgetType::kIntegerInputBox) {
    input_box_suffix = r.text(kInputBoxSuffixSize);
  }
  return Status::ok();
}

void WidgetListDataAck::describe(FieldSink& sink) const {
  codec::detail::SinkAdapter out{sink};
  out("type", type);
  out("index", index);
  out("name", name);
  if (type == WidgetType::kChooseList) {
    out("choose_item_count", choose_item_count);
    for (size_t i = 0; i < choose_item_count && i < kMaxChooseItems; ++i) {
      IndexedSink item(sink, "choose_item", i + 1);
      item.text("name", choose_items[i]);
    }
  } else if (type == WidgetType::kIntegerInputBox) {
    out("input_box_suffix", input_box_suffix);
  }
}

// --- 3.2.7 ACK ----------------------------------------------------------------------------------

Status WidgetGroupDataAck::validate() const {
  Status s = check_int("count", count, 1, kMaxWidgetsPerGroup);
  for (size_t i = 0; s && i < count; ++i) s = check_enum("type", widgets[i].type);
  return s;
}

void WidgetGroupDataAck::encode(ByteWriter& w) const {
  w.u8(count);
  for (size_t i = 0; i < count; ++i) WidgetValue::layout(widgets[i], LayoutWriter(w));
}

Status WidgetGroupDataAck::decode(ByteReader& r) {
  count = r.u8();
  if (count > kMaxWidgetsPerGroup) {
    return Status::fail("group of " + std::to_string(count) + " widgets, at most 15 allowed");
  }
  for (size_t i = 0; i < count; ++i) WidgetValue::layout(widgets[i], LayoutReader(r));
  return Status::ok();
}

void WidgetGroupDataAck::describe(FieldSink& sink) const {
  sink.unsigned_integer("count", count);
  for (size_t i = 0; i < count && i < kMaxWidgetsPerGroup; ++i) {
    IndexedSink widget(sink, "widget", i + 1);
    WidgetValue::layout(widgets[i], LayoutSink(widget));
  }
}

}  // namespace k40t::psdk
