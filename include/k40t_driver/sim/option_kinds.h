// The kinds of option both simulators (k40t_sim, skyport_sim) have, as OptionSpec builders: each
// one checks its value and writes one field of the options struct, so a table entry says only
// which option, which field and which range.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "k40t_driver/sim/number_text.h"
#include "k40t_driver/sim/option_table.h"
#include "k40t_driver/sim/sim_options.h"

namespace k40t::sim {

template <class Options>
struct OptionKinds {
  using Spec = OptionSpec<Options>;
  // Where an option writes: the field of the options it sets.
  template <class T>
  using Field = T& (*)(Options&);

  // A number within [lo, hi] becomes `field`, converted to its type.
  template <class T>
  static Spec number(const char* name, const char* argument, const char* help, double lo, double hi,
                     Field<T> field) {
    return number_to(name, argument, help, lo, hi,
                     [field](Options& o, double n) { field(o) = static_cast<T>(n); });
  }

  // A number within [lo, hi] handed to `set`: for a field that wants it in other units, or for
  // several fields.
  static Spec number_to(const char* name, const char* argument, const char* help, double lo,
                        double hi, std::function<void(Options&, double)> set) {
    return {name, argument, help, [=](Options& o, const std::string& option, const std::string& v) {
              const auto n = parse_number_in(v, option, lo, hi);
              if (!n) return n.status();
              set(o, *n);
              return Status::ok();
            }};
  }

  // A flag: present, `field` is true.
  static Spec flag(const char* name, const char* help, Field<bool> field) {
    return {name, nullptr, help, [=](Options& o, const std::string&, const std::string&) {
              field(o) = true;
              return Status::ok();
            }};
  }

  // Text that must not be empty.
  static Spec text(const char* name, const char* argument, const char* help,
                   Field<std::string> field) {
    return text_into(name, argument, help, field);
  }
  static Spec text(const char* name, const char* argument, const char* help,
                   Field<std::optional<std::string>> field) {
    return text_into(name, argument, help, field);
  }

  // --link: the host's view of the link, kept as the server side the simulator opens
  // (server_side_url) in `o.link`.
  static Spec link(const char* help) {
    return {"--link", "URL", help, [](Options& o, const std::string&, const std::string& v) {
              const auto url = server_side_url(v);
              if (!url) return url.status();
              o.link = *url;
              return Status::ok();
            }};
  }

  // "AT:AMOUNT": a fault of `kind` scheduled AT seconds after the start, added to `o.scheduled`.
  static Spec scheduled(const char* name, const char* argument, const char* help,
                        ScheduledFault::Kind kind, double max_amount) {
    return {name, argument, help, [=](Options& o, const std::string& option, const std::string& v) {
              const auto fault = parse_scheduled_fault(option, v, kind, max_amount);
              if (!fault) return fault.status();
              o.scheduled.push_back(*fault);
              return Status::ok();
            }};
  }

 private:
  template <class Text>
  static Spec text_into(const char* name, const char* argument, const char* help,
                        Field<Text> field) {
    return {name, argument, help, [=](Options& o, const std::string& option, const std::string& v) {
              if (v.empty()) return Status::fail(option + ": empty");
              field(o) = v;
              return Status::ok();
            }};
  }
};

}  // namespace k40t::sim
