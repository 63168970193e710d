// How the entries of the settings table (settings_bindings.cpp) are written: one expression per
// setting, e.g.
//   one_field<p::ThermalSharpnessRequest>("thermal_sharpness", &Req::sharpness,
//   &C::thermal_sharpness)
//       .reads(&p::ThermalSettingsAck::sharpness)
// gives the binding, its request id and its read-back together; a setting of
// several parameters lists them as fields<Req>(name, from(&Req::a, &C::a), ...).reads(&Ack::a,
// ...), or writes its request and read-back out with group() and reads_with().
#pragma once

#include <tuple>
#include <type_traits>
#include <utility>

#include "k40t_driver/ros/setting_binding.h"

namespace k40t::driver::setting_table {

// A table entry under construction; converts to the finished SettingBinding.
class Entry {
 public:
  explicit Entry(SettingBinding binding) : binding_(std::move(binding)) {}

  // Read back from `Report` by `read(config, report)`.
  template <class Report, class Read>
  Entry&& reads_with(Read read) && {
    binding_.read_from = Report::kId;
    binding_.read_back = [read](Config& c, const SettingReports& reports) {
      if (const Report* report = std::get<const Report*>(reports)) read(c, *report);
    };
    return std::move(*this);
  }
  // No report carries it (stated, so that every entry says where its value comes back from).
  Entry&& write_only() && { return std::move(*this); }
  Entry&& service(std::string name) && {
    binding_.service = std::move(name);
    return std::move(*this);
  }
  // For one of two settings the pod will not have on at once (3.2.3.9/3.2.3.10 note).
  template <class Member>
  Entry&& sent_first_when_off(Member member) && {
    binding_.switches_off = [member](const Config& next, const Config& current) {
      return current.*member && !(next.*member);
    };
    return std::move(*this);
  }
  operator SettingBinding() && { return std::move(binding_); }  // NOLINT: the table's element

 protected:
  SettingBinding binding_;
};

// A binding for the parameters `members`, sent together as the request build(config) returns.
template <class Build, class... Members>
Entry group(std::string name, Build build, Members... members) {
  using Request = decltype(build(std::declval<const Config&>()));
  SettingBinding b;
  b.name = std::move(name);
  b.request = Request::kId;
  b.request_name = Request::kName;
  b.differs = [=](const Config& a, const Config& c) { return ((a.*members != c.*members) || ...); };
  b.copy = [=](Config& to, const Config& from) { ((to.*members = from.*members), ...); };
  b.apply = [build](PodDriver& driver, const Config& c) { return driver.request(build(c)); };
  return Entry(std::move(b));
}

// One request field and the parameter it is sent from: an argument of fields().
template <class ReqField, class T>
struct FieldOf {
  ReqField request;
  T Config::*member;
};
template <class ReqField, class T>
FieldOf<ReqField, T> from(ReqField request, T Config::*member) {
  return {request, member};
}

// The common case: each parameter goes to one field of the request and, when it is read back,
// comes from one field of a report, in the same order (enums, switches and levels alike).
template <class... Members>
class Fields : public Entry {
 public:
  Fields(Entry entry, Members... members) : Entry(std::move(entry)), members_(members...) {}

  // The report is the fields' class, or `Report` when named (reads<Camera>(...)): a field may
  // be a member of a base the report shares with a request (PhotoSettings).
  template <class Report = void, class... Owners, class... V>
  Entry&& reads(V Owners::*... fields) && {
    static_assert(sizeof...(V) == sizeof...(Members), "one report field per parameter");
    using From = std::conditional_t<std::is_void_v<Report>,
                                    std::tuple_element_t<0, std::tuple<Owners...>>, Report>;
    return std::move(*this).template reads_with<From>(
        [members = members_, fields...](Config& c, const From& r) {
          std::apply(
              [&](auto... member) {
                ((c.*member = static_cast<std::decay_t<decltype(c.*member)>>(r.*fields)), ...);
              },
              members);
        });
  }

 private:
  std::tuple<Members...> members_;
};

template <class Req, class... ReqFields, class... Ts>
Fields<Ts Config::*...> fields(std::string name, FieldOf<ReqFields, Ts>... pairs) {
  auto build = [pairs...](const Config& c) {
    Req r;
    ((r.*pairs.request = static_cast<std::decay_t<decltype(r.*pairs.request)>>(c.*pairs.member)),
     ...);
    return r;
  };
  return Fields<Ts Config::*...>(group(std::move(name), build, pairs.member...), pairs.member...);
}

template <class Req, class ReqField, class T>
Fields<T Config::*> one_field(std::string name, ReqField field, T Config::*member) {
  return fields<Req>(std::move(name), from(field, member));
}

}  // namespace k40t::driver::setting_table
