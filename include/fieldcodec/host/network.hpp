// fieldcodec — host adapters: host::network, one object that owns the loop every host program
// otherwise writes: a bus, a steady millisecond clock, and any number of machines (a
// node::device, SDO clients and servers, master::boot, master::configurator, …: anything with
// the canopen/step.hpp shape `on_frame(frame, now)` and `poll(now)` returning a canopen::step).
//
//   host::network net(bus);
//   auto id = net.add(dev);                          // the machine, borrowed
//   (void)net.send(id, dev.start(net.now()));         // what a start call returned
//   while (running) if (auto r = net.run_once(100ms); !r) { puts(r.error().what.c_str()); }
//
// run_once waits for one frame until the earliest deadline of its machines (at most
// `max_wait`), gives the frame to every machine it concerns (all of them, or those whose
// filter takes it), sends what each returns, and polls every machine whose deadline has come.
// A frame one machine sends is also given to the network's other machines, as a CAN bus shows
// every frame to every other node (so a node and a client of it may share one network); never
// back to its sender.
//
// Errors are values (network_error: the errc, the machine, one line of text). A bus that fails
// to send or receive stops the call (bad_state, or the bus's errc; `bus` holds the bus's context);
// error-passive and other warning error frames are counted (warnings()) and the loop goes on, as
// host::sdo_session does; a bus-off is an error. A machine whose start call failed
// (send(id, result)) is reported with that errc and sends nothing.
//
// Host only (heap, std::function): firmware runs its machines from its own loop.
#pragma once

#include <fieldcodec/canopen/abort_code.hpp>
#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/step.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/host/bus.hpp>
#include <fieldcodec/host/clock.hpp>
#include <fieldcodec/host/deadline.hpp>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace fieldcodec::host {

/// Why a network call stopped.
struct network_error {
  errc code = errc::bad_state;
  /// The machine concerned (add()'s id), when one is; empty for a bus failure.
  std::optional<std::size_t> machine{};
  bool bus_failed = false; ///< the bus failed (bus holds its context)
  bus_error bus{};
  std::string what; ///< one line
};

/// Anything the network can run: on_frame(frame, now) and poll(now) returning a canopen::step.
template <class M>
concept network_machine = requires(M &m, const canopen::can_frame &f, std::uint32_t now) {
  m.on_frame(f, now).send;
  m.on_frame(f, now).deadline;
  m.poll(now).send;
  m.poll(now).deadline;
};

class network {
public:
  /// A network on `bus` (borrowed; must outlive the network). Its clock starts now.
  explicit network(can_bus &bus) : bus_(&bus) {}
  network(const network &) = delete;
  network &operator=(const network &) = delete;

  /// The machines' `now`: milliseconds since the network was made.
  [[nodiscard]] std::uint32_t now() const noexcept { return clock_.now(); }
  [[nodiscard]] const steady_ms &clock() const noexcept { return clock_; }
  [[nodiscard]] can_bus &bus() noexcept { return *bus_; }

  /// Run `m` (borrowed; it must outlive the network or be removed first). `after`, if given, is
  /// called with every step the machine returns (its frames already sent) and the time: the
  /// place to look at the machine's state and events. Returns the machine's id.
  template <network_machine M>
  std::size_t add(M &m) {
    return add(m, [](const auto &, std::uint32_t) {});
  }
  template <network_machine M, class After>
  std::size_t add(M &m, After after) {
    auto s = std::make_unique<slot_of<M, After>>(m, std::move(after));
    slots_.push_back(std::move(s));
    return slots_.size() - 1U;
  }
  /// Give machine `id` only the frames `accepts` takes (e.g. by COB-ID); by default every
  /// frame (each machine ignores what is not its own, but a filter saves the calls).
  void filter(std::size_t id, std::function<bool(const canopen::can_frame &)> accepts) {
    if (id < slots_.size() && slots_[id]) slots_[id]->accepts = std::move(accepts);
  }
  /// Stop running machine `id` (it is never called again; the id is not reused).
  void remove(std::size_t id) {
    if (id < slots_.size()) slots_[id].reset();
  }
  /// Machines running.
  [[nodiscard]] std::size_t size() const noexcept {
    std::size_t n = 0;
    for (const auto &s : slots_) n += s ? 1U : 0U;
    return n;
  }

  /// Send what a call into machine `id` outside the loop returned (start(), an SDO client's
  /// upload(), a device's set()), keep its deadline, and give its frames to the other
  /// machines. Returns the step's state. Errors: the call's own errc (nothing sent; an abort
  /// code as canopen::sdo::to_errc maps it), those of a failing bus; invalid_argument for an
  /// unknown id.
  template <class S>
  result<S, network_error> send(std::size_t id, const canopen::step<S> &s) {
    if (id >= slots_.size() || !slots_[id]) return unknown(id);
    slots_[id]->deadline = s.deadline;
    if (auto r = transmit(id, s.send); !r) return r.error();
    if (auto r = deliver(); !r) return r.error();
    return s.state;
  }
  template <class S, class E>
  result<S, network_error> send(std::size_t id, const result<canopen::step<S>, E> &r) {
    if (!r) {
      network_error e;
      e.code = to_errc(r.error());
      e.machine = id;
      e.what = "machine " + std::to_string(id) + ": " + std::string(to_string(e.code));
      return e;
    }
    return send(id, r.value());
  }

  /// One turn: wait for a frame until the earliest deadline (at most `max_wait`), give it to
  /// the machines, then poll each machine whose deadline has come; every frame they return is
  /// sent. A timeout of the bus is no error. Errors: see the top of the file.
  result<void, network_error> run_once(std::chrono::milliseconds max_wait) {
    std::chrono::milliseconds wait = max_wait;
    const std::uint32_t t = now();
    for (const auto &s : slots_) {
      if (!s || !s->deadline) continue;
      const std::uint32_t d = *s->deadline;
      const auto left =
          canopen::reached(d, t) ? std::chrono::milliseconds(0) : std::chrono::milliseconds(d - t);
      if (left < wait) wait = left;
    }
    auto r = bus_->receive(wait);
    if (r) {
      if (auto d = dispatch(r.value().frame, nobody); !d) return d.error();
    } else if (r.error() != errc::timeout) {
      const bus_error &be = bus_->last_error();
      if (!be.from_error_frame || be.frame.is_bus_off()) return bus_failed();
      ++warnings_;
    }
    return poll_due();
  }

  /// run_once until `ms` have passed.
  result<void, network_error> run_for(std::chrono::milliseconds ms) {
    const auto end = std::chrono::steady_clock::now() + ms;
    for (;;) {
      const auto left = time_left(end);
      if (left.count() == 0) return {};
      if (auto r = run_once(left); !r) return r;
    }
  }

  /// run_once until `done()` is true (checked before each turn); timeout (network_error with
  /// no machine) when it is not within `ms`.
  template <class Done>
  result<void, network_error> run_until(Done done, std::chrono::milliseconds ms) {
    const auto end = std::chrono::steady_clock::now() + ms;
    for (;;) {
      if (done()) return {};
      const auto left = time_left(end);
      if (left.count() == 0) {
        network_error e;
        e.code = errc::timeout;
        e.what = "not done within " + std::to_string(ms.count()) + " ms";
        return e;
      }
      if (auto r = run_once(left); !r) return r;
    }
  }

  /// Error frames that were only warnings (error passive, error counters), skipped.
  [[nodiscard]] std::size_t warnings() const noexcept { return warnings_; }

private:
  static constexpr std::size_t nobody = static_cast<std::size_t>(-1);

  struct slot {
    virtual ~slot() = default;
    // call the machine; its frames go to `net` through transmit
    virtual result<void, network_error> frame(network &net, std::size_t id,
                                              const canopen::can_frame &f, std::uint32_t now) = 0;
    virtual result<void, network_error> poll(network &net, std::size_t id, std::uint32_t now) = 0;
    std::optional<std::uint32_t> deadline{};
    std::function<bool(const canopen::can_frame &)> accepts{};
  };

  template <class M, class After>
  struct slot_of final : slot {
    slot_of(M &m, After a) : machine(&m), after(std::move(a)) {}
    template <class Step>
    result<void, network_error> take(network &net, std::size_t id, const Step &s,
                                     std::uint32_t now) {
      deadline = s.deadline;
      auto r = net.transmit(id, s.send);
      after(s, now);
      return r;
    }
    result<void, network_error> frame(network &net, std::size_t id, const canopen::can_frame &f,
                                      std::uint32_t now) override {
      return take(net, id, machine->on_frame(f, now), now);
    }
    result<void, network_error> poll(network &net, std::size_t id, std::uint32_t now) override {
      return take(net, id, machine->poll(now), now);
    }
    M *machine;
    After after;
  };

  // the errc of a call's error: an errc, an abort code (a device's set()), or an error with
  // a `code`
  template <class E>
  static errc to_errc(const E &e) {
    if constexpr (std::is_same_v<E, errc>) {
      return e;
    } else if constexpr (std::is_same_v<E, canopen::sdo::abort_code>) {
      return canopen::sdo::to_errc(e);
    } else {
      return e.code;
    }
  }

  network_error unknown(std::size_t id) const {
    network_error e;
    e.code = errc::invalid_argument;
    e.machine = id;
    e.what = "machine " + std::to_string(id) + ": not on the network";
    return e;
  }

  network_error bus_failed() const {
    network_error e;
    e.bus = bus_->last_error();
    e.code = e.bus.code;
    e.bus_failed = true;
    e.what = e.bus.what;
    return e;
  }

  // Send the frames of `from`'s step (read now: they are valid until the next call into it)
  // and queue them for the other machines.
  result<void, network_error> transmit(std::size_t from, const canopen::frames &fs) {
    for (const canopen::can_frame &f : fs) {
      if (!bus_->send(f)) {
        network_error e = bus_failed();
        e.machine = from;
        return e;
      }
      if (slots_.size() > 1U) local_.emplace_back(f, from);
    }
    return {};
  }

  // Give the queued frames of machines to the others, until none is left.
  result<void, network_error> deliver() {
    while (!local_.empty()) {
      const auto [f, from] = local_.front();
      local_.pop_front();
      if (auto r = give(f, from); !r) {
        local_.clear();
        return r;
      }
    }
    return {};
  }

  result<void, network_error> give(const canopen::can_frame &f, std::size_t from) {
    for (std::size_t i = 0; i < slots_.size(); ++i) {
      slot *s = slots_[i].get();
      if (s == nullptr || i == from || (s->accepts && !s->accepts(f))) continue;
      if (auto r = s->frame(*this, i, f, now()); !r) return r;
    }
    return {};
  }

  result<void, network_error> dispatch(const canopen::can_frame &f, std::size_t from) {
    if (auto r = give(f, from); !r) {
      local_.clear();
      return r;
    }
    return deliver();
  }

  result<void, network_error> poll_due() {
    for (std::size_t i = 0; i < slots_.size(); ++i) {
      slot *s = slots_[i].get();
      if (s == nullptr || !s->deadline || !canopen::reached(*s->deadline, now())) continue;
      if (auto r = s->poll(*this, i, now()); !r) {
        local_.clear();
        return r;
      }
      if (auto r = deliver(); !r) return r;
    }
    return {};
  }

  can_bus *bus_;
  steady_ms clock_{};
  std::vector<std::unique_ptr<slot>> slots_;
  std::deque<std::pair<canopen::can_frame, std::size_t>> local_;
  std::size_t warnings_ = 0;
};

} // namespace fieldcodec::host
