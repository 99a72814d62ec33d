// fieldcodec — host adapter: a Linux SocketCAN interface (raw CAN socket) as a host::can_bus.
//
//   host::socketcan_bus bus;
//   if (!bus.open("can0")) die(bus.last_error().what);
//   bus.set_filters({{0x585, 0x7FF}});          // optional: only these identifiers
//   bus.send(frame);
//   auto r = bus.receive(std::chrono::milliseconds(500));
//
// Error frames are on (every controller error class): receive() reports them as errors
// (bad_state; last_error().frame says bus-off, error passive, ...), receive_record() returns
// them as records. Frames get the kernel's receive time (SO_TIMESTAMP). Empty where
// <linux/can.h> does not exist.
#pragma once

#include <fieldcodec/host/socketcan.hpp>

#ifdef FIELDCODEC_HAS_SOCKETCAN

#include <fieldcodec/host/bus.hpp>

#include <linux/can.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fieldcodec::host {

/// One receive filter: a frame passes when (id & mask) == (filter id & mask).
struct can_filter {
  std::uint32_t id = 0;
  std::uint32_t mask = 0x7FF;
  bool extended = false; ///< match 29-bit frames (else base frames only)
};

class socketcan_bus final : public can_bus {
public:
  socketcan_bus() = default;
  ~socketcan_bus() override { close(); }

  /// Open the interface `iface` ("can0", "vcan0"). Errors: too_long / bad_character (not an
  /// interface name), invalid_argument (no such interface), access_denied, bad_state (socket
  /// could not be made or bound; last_error() has errno).
  status open(std::string_view iface) {
    close();
    name_ = std::string(iface);
    auto n = interface_name::make(iface);
    if (!n) return fail(n.error(), 0, "not an interface name");
    iface_ = n.value();
    const unsigned index = ::if_nametoindex(name_.c_str());
    if (index == 0U) return fail(errc::invalid_argument, 0, "no such network interface");
    const int fd = ::socket(PF_CAN, SOCK_RAW | SOCK_CLOEXEC, CAN_RAW);
    if (fd < 0) return fail(errc::bad_state, errno, "no CAN socket");
    fd_ = fd;
    const can_err_mask_t all_errors = CAN_ERR_MASK;
    ::setsockopt(fd_, SOL_CAN_RAW, CAN_RAW_ERR_FILTER, &all_errors, sizeof all_errors);
    const int on = 1;
    ::setsockopt(fd_, SOL_SOCKET, SO_TIMESTAMP, &on, sizeof on);
    sockaddr_can addr{};
    addr.can_family = AF_CAN;
    addr.can_ifindex = static_cast<int>(index);
    if (::bind(fd_, reinterpret_cast<const sockaddr *>(&addr), sizeof addr) != 0) {
      const int e = errno;
      close();
      return fail(e == EACCES || e == EPERM ? errc::access_denied : errc::bad_state, e, "bind");
    }
    return {};
  }

  /// Only frames matching one of `filters` are received (error frames always are). An empty
  /// list receives nothing but error frames. Errors: bad_state (not open, setsockopt failed).
  status set_filters(std::span<const can_filter> filters) {
    if (fd_ < 0) return fail(errc::bad_state, 0, "not open");
    std::vector<::can_filter> f;
    f.reserve(filters.size());
    for (const can_filter &c : filters) {
      ::can_filter k{};
      k.can_id = c.extended ? ((c.id & CAN_EFF_MASK) | CAN_EFF_FLAG) : (c.id & CAN_SFF_MASK);
      // CAN_EFF_FLAG in the mask: the frame format must match too.
      k.can_mask = (c.mask & (c.extended ? CAN_EFF_MASK : CAN_SFF_MASK)) | CAN_EFF_FLAG;
      f.push_back(k);
    }
    const auto size = static_cast<socklen_t>(f.size() * sizeof(::can_filter));
    if (::setsockopt(fd_, SOL_CAN_RAW, CAN_RAW_FILTER, f.empty() ? nullptr : f.data(), size) != 0) {
      return fail(errc::bad_state, errno, "CAN_RAW_FILTER");
    }
    return {};
  }
  status set_filters(std::initializer_list<can_filter> filters) {
    return set_filters(std::span<const can_filter>(filters.begin(), filters.size()));
  }

  status send(const canopen::can_frame &f) override {
    if (fd_ < 0) return fail(errc::bad_state, 0, "not open");
    auto s = to_socketcan(f);
    if (!s) return fail(s.error(), 0, "not a CAN frame");
    // A full transmit queue (ENOBUFS) drains as the controller sends: wait for it a while.
    for (int attempt = 0; attempt < 100; ++attempt) {
      const ssize_t n = ::write(fd_, &s.value(), sizeof(::can_frame));
      if (n == static_cast<ssize_t>(sizeof(::can_frame))) return {};
      if (n < 0 && errno == EINTR) continue;
      if (n < 0 && (errno == ENOBUFS || errno == EAGAIN)) {
        pollfd p{fd_, POLLOUT, 0};
        ::poll(&p, 1, 10);
        continue;
      }
      return fail(errc::bad_state, n < 0 ? errno : EIO, "write");
    }
    return fail(errc::timeout, ENOBUFS, "transmit queue full");
  }

  result<frame_record> receive_record(std::chrono::milliseconds timeout) override {
    if (fd_ < 0) return fail(errc::bad_state, 0, "not open");
    pollfd p{fd_, POLLIN, 0};
    int ready = 0;
    do {
      ready = ::poll(&p, 1, static_cast<int>(timeout.count()));
    } while (ready < 0 && errno == EINTR);
    if (ready < 0) return fail(errc::bad_state, errno, "poll");
    if (ready == 0) return fail(errc::timeout, 0, "no frame in time");
    ::can_frame in{};
    iovec io{&in, sizeof in};
    alignas(cmsghdr) char control[CMSG_SPACE(sizeof(timeval))]{};
    msghdr msg{};
    msg.msg_iov = &io;
    msg.msg_iovlen = 1;
    msg.msg_control = control;
    msg.msg_controllen = sizeof control;
    const ssize_t n = ::recvmsg(fd_, &msg, 0);
    if (n < 0) return fail(errc::bad_state, errno, "read");
    if (n != static_cast<ssize_t>(sizeof in)) return fail(errc::bad_length, 0, "short read");
    frame_record r;
    r.iface = iface_;
    r.time = receive_time(msg);
    r.error = (in.can_id & CAN_ERR_FLAG) != 0U;
    r.extended = !r.error && (in.can_id & CAN_EFF_FLAG) != 0U;
    r.rtr = !r.error && (in.can_id & CAN_RTR_FLAG) != 0U;
    r.id = r.error      ? (in.can_id & CAN_ERR_MASK)
           : r.extended ? (in.can_id & CAN_EFF_MASK)
                        : (in.can_id & CAN_SFF_MASK);
    r.dlc = in.can_dlc > 8U ? std::uint8_t{8} : in.can_dlc;
    if (!r.rtr) {
      for (std::size_t i = 0; i < r.dlc; ++i) r.data[i] = in.data[i];
    }
    return r;
  }

  /// Close the socket (also done by the destructor).
  void close() noexcept {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }
  [[nodiscard]] bool is_open() const noexcept { return fd_ >= 0; }
  /// The socket (for poll() with other descriptors); -1 when closed.
  [[nodiscard]] int native_handle() const noexcept { return fd_; }

private:
  static timestamp receive_time(const msghdr &msg) noexcept {
    for (const cmsghdr *c = CMSG_FIRSTHDR(&msg); c != nullptr;
         c = CMSG_NXTHDR(const_cast<msghdr *>(&msg), const_cast<cmsghdr *>(c))) {
      if (c->cmsg_level == SOL_SOCKET && c->cmsg_type == SO_TIMESTAMP) {
        timeval tv{};
        std::memcpy(&tv, CMSG_DATA(c), sizeof tv);
        return timestamp{tv.tv_sec, static_cast<std::uint32_t>(tv.tv_usec), 6};
      }
    }
    const auto now = std::chrono::system_clock::now().time_since_epoch();
    return timestamp::from_microseconds(
        std::chrono::duration_cast<std::chrono::microseconds>(now).count());
  }

  int fd_ = -1;
  interface_name iface_{};
};

} // namespace fieldcodec::host

#endif // FIELDCODEC_HAS_SOCKETCAN
