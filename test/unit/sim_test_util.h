// Shared helpers of the simulator's model tests: advance a model in fixed steps (no sleeping) and
// pick events of one kind out of a queue.
#pragma once

#include <cmath>
#include <variant>
#include <vector>

#include "k40t_driver/sim/events.h"

namespace k40t::sim::testing {

constexpr double kStepS = 0.01;

// Calls step(dt) until `seconds` of model time have passed.
template <class Model>
void advance(Model& model, double seconds, EventQueue& events, double dt = kStepS) {
  const int steps = static_cast<int>(std::lround(seconds / dt));
  for (int i = 0; i < steps; ++i) model.step(dt, events);
}

template <class Event>
std::vector<Event> events_of(const EventQueue& events) {
  std::vector<Event> out;
  for (const PodEvent& event : events) {
    if (const Event* e = std::get_if<Event>(&event)) out.push_back(*e);
  }
  return out;
}

// The `state` of each event of type Event, in order.
template <class Event>
auto states_of(const EventQueue& events) {
  std::vector<decltype(Event::state)> out;
  for (const Event& e : events_of<Event>(events)) out.push_back(e.state);
  return out;
}

}  // namespace k40t::sim::testing
