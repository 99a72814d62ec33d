// fieldcodec — host adapter: a serial port (POSIX termios): raw mode, line settings, reads with
// a timeout. Used by the slcan adapter (host/slcan.hpp) and by device links over RS232 (each
// device adapter names its own line settings).
//
//   host::serial_port port;
//   const host::line_settings line{9600, 7, host::parity::none, 1, false};   // 9600 7N1
//   if (!port.open("/dev/ttyUSB0", line)) die(port.last_error().what);
//   port.write(bytes);
//   auto n = port.read(buffer, std::chrono::milliseconds(200));   // timeout: nothing came
#pragma once

#if defined(__has_include)
#if __has_include(<termios.h>) && __has_include(<poll.h>)
#define FIELDCODEC_HAS_TERMIOS 1
#endif
#endif

#ifdef FIELDCODEC_HAS_TERMIOS

#include <fieldcodec/core/result.hpp>
#include <fieldcodec/host/bus.hpp>
#include <fieldcodec/host/deadline.hpp>

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <string_view>

namespace fieldcodec::host {

enum class parity : std::uint8_t { none, even, odd };

/// The line settings of a serial port.
struct line_settings {
  std::uint32_t baud = 9600;
  std::uint8_t data_bits = 8; ///< 5..8
  parity par = parity::none;
  std::uint8_t stop_bits = 1; ///< 1 or 2
  bool rts_cts = false;       ///< hardware flow control (RTS/CTS)
};

/// A serial link to an slcan adapter: 115200 baud 8N1 (USB adapters ignore the rate).
inline constexpr line_settings slcan_line{115200, 8, parity::none, 1, false};

/// The termios speed constant of a baud rate; 0 when it has none.
[[nodiscard]] constexpr speed_t termios_speed(std::uint32_t baud) noexcept {
  switch (baud) {
  case 50: return B50;
  case 75: return B75;
  case 110: return B110;
  case 134: return B134;
  case 150: return B150;
  case 200: return B200;
  case 300: return B300;
  case 600: return B600;
  case 1200: return B1200;
  case 1800: return B1800;
  case 2400: return B2400;
  case 4800: return B4800;
  case 9600: return B9600;
  case 19200: return B19200;
  case 38400: return B38400;
  case 57600: return B57600;
  case 115200: return B115200;
  case 230400: return B230400;
#ifdef B460800
  case 460800: return B460800;
#endif
#ifdef B921600
  case 921600: return B921600;
#endif
#ifdef B1000000
  case 1000000: return B1000000;
#endif
#ifdef B2000000
  case 2000000: return B2000000;
#endif
#ifdef B3000000
  case 3000000: return B3000000;
#endif
  default: return 0;
  }
}

/// Check line settings. Errors: invalid_argument (a baud rate without a termios constant, data
/// bits not 5..8, stop bits not 1 or 2).
[[nodiscard]] constexpr status check(const line_settings &s) noexcept {
  if (termios_speed(s.baud) == 0) return errc::invalid_argument;
  if (s.data_bits < 5U || s.data_bits > 8U) return errc::invalid_argument;
  if (s.stop_bits != 1U && s.stop_bits != 2U) return errc::invalid_argument;
  return {};
}

/// Set `t` to raw mode with the settings `s` (what serial_port::open asks of the driver; a
/// pseudo-terminal keeps only some of it: Linux forces 8 data bits without parity there).
inline void apply(const line_settings &s, termios &t) noexcept {
  ::cfmakeraw(&t);
  t.c_cflag &= ~static_cast<tcflag_t>(CSIZE | PARENB | PARODD | CSTOPB | CRTSCTS);
  t.c_cflag |= CREAD | CLOCAL;
  switch (s.data_bits) {
  case 5: t.c_cflag |= CS5; break;
  case 6: t.c_cflag |= CS6; break;
  case 7: t.c_cflag |= CS7; break;
  default: t.c_cflag |= CS8; break;
  }
  if (s.par != parity::none) t.c_cflag |= PARENB;
  if (s.par == parity::odd) t.c_cflag |= PARODD;
  if (s.stop_bits == 2U) t.c_cflag |= CSTOPB;
  if (s.rts_cts) t.c_cflag |= CRTSCTS;
  t.c_iflag &= ~static_cast<tcflag_t>(IXON | IXOFF | IXANY | ISTRIP | INPCK);
  if (s.par != parity::none) t.c_iflag |= INPCK;
  t.c_cc[VMIN] = 0;
  t.c_cc[VTIME] = 0;
  const speed_t speed = termios_speed(s.baud);
  ::cfsetispeed(&t, speed);
  ::cfsetospeed(&t, speed);
}

/// A serial port in raw mode. Not copyable; errors keep their context in last_error().
class serial_port {
public:
  serial_port() = default;
  serial_port(const serial_port &) = delete;
  serial_port &operator=(const serial_port &) = delete;
  ~serial_port() { close(); }

  /// Open `path` with `settings` (raw: no echo, no line editing, no character translation).
  /// Errors: invalid_argument (settings, or no such file), access_denied, bad_state (not a
  /// terminal, or termios refused the settings; last_error() has errno).
  status open(std::string_view path, const line_settings &settings) {
    close();
    name_ = std::string(path);
    if (!check(settings)) return fail(errc::invalid_argument, 0, "unsupported line settings");
    const int fd = ::open(name_.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
      const int e = errno;
      return fail(e == EACCES || e == EPERM                  ? errc::access_denied
                  : e == ENOENT || e == ENXIO || e == ENODEV ? errc::invalid_argument
                                                             : errc::bad_state,
                  e, "open");
    }
    fd_ = fd;
    return configure(settings);
  }

  /// Adopt an open descriptor (a pseudo-terminal, a socket pair) and configure it when it is a
  /// terminal. The port closes it.
  status adopt(int fd, std::string_view name, const line_settings &settings) {
    close();
    name_ = std::string(name);
    fd_ = fd;
    ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) | O_NONBLOCK);
    if (::isatty(fd_) == 0) return {};
    return configure(settings);
  }

  /// Write all of `bytes`, waiting at most `timeout` for the line to take them.
  /// Errors: bad_state (not open, write failed), timeout.
  status write(std::span<const std::uint8_t> bytes,
               std::chrono::milliseconds timeout = std::chrono::milliseconds(1000)) {
    if (fd_ < 0) return fail(errc::bad_state, 0, "not open");
    const auto end = std::chrono::steady_clock::now() + timeout;
    std::size_t done = 0;
    while (done < bytes.size()) {
      const ssize_t n = ::write(fd_, bytes.data() + done, bytes.size() - done);
      if (n > 0) {
        done += static_cast<std::size_t>(n);
        continue;
      }
      if (n < 0 && errno == EINTR) continue;
      if (n < 0 && errno != EAGAIN) return fail(errc::bad_state, errno, "write");
      const int left = poll_ms(end);
      if (left == 0) return fail(errc::timeout, 0, "write: the line does not take more bytes");
      pollfd p{fd_, POLLOUT, 0};
      ::poll(&p, 1, left);
    }
    return {};
  }
  status write(std::string_view text,
               std::chrono::milliseconds timeout = std::chrono::milliseconds(1000)) {
    return write(std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t *>(text.data()),
                                               text.size()),
                 timeout);
  }

  /// Read what has arrived into `out`, waiting at most `timeout` for the first byte; returns
  /// the number of bytes (at least 1). Errors: timeout (nothing came), bad_state (not open,
  /// read failed, the other side hung up).
  result<std::size_t> read(std::span<std::uint8_t> out, std::chrono::milliseconds timeout) {
    if (fd_ < 0) return fail(errc::bad_state, 0, "not open");
    if (out.empty()) return fail(errc::buffer_too_small, 0, "read: no room");
    const auto end = std::chrono::steady_clock::now() + timeout;
    for (;;) {
      // poll first: in raw mode (VMIN = VTIME = 0) read() returns 0 both for "nothing yet"
      // and for a line that is gone, poll() tells them apart.
      const int left = poll_ms(end);
      pollfd p{fd_, POLLIN, 0};
      const int ready = ::poll(&p, 1, left);
      if (ready < 0 && errno == EINTR) continue;
      if (ready < 0) return fail(errc::bad_state, errno, "poll");
      if (ready == 0) {
        if (left == 0) return fail(errc::timeout, 0, "no answer in time");
        continue;
      }
      if ((p.revents & POLLIN) == 0) {
        return fail(errc::bad_state, 0, "the other side closed the line");
      }
      const ssize_t n = ::read(fd_, out.data(), out.size());
      if (n > 0) return static_cast<std::size_t>(n);
      if (n == 0) return fail(errc::bad_state, 0, "the other side closed the line");
      if (errno == EINTR || errno == EAGAIN) continue;
      if (errno == EIO) return fail(errc::bad_state, errno, "the other side hung up");
      return fail(errc::bad_state, errno, "read");
    }
  }

  /// Drop everything received and not yet read.
  void discard_input() noexcept {
    if (fd_ >= 0) ::tcflush(fd_, TCIFLUSH);
  }

  void close() noexcept {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }
  [[nodiscard]] bool is_open() const noexcept { return fd_ >= 0; }
  [[nodiscard]] int native_handle() const noexcept { return fd_; }
  [[nodiscard]] std::string_view name() const noexcept { return name_; }
  [[nodiscard]] const bus_error &last_error() const noexcept { return error_; }

private:
  /// poll()'s timeout for a wait until `end`: time_left (0 once less than a millisecond is
  /// left), at most 60 s per call (poll takes an int; the loops call again).
  static int poll_ms(std::chrono::steady_clock::time_point end) noexcept {
    const auto left = time_left(end).count();
    return static_cast<int>(left > 60'000 ? 60'000 : left);
  }

  status configure(const line_settings &s) {
    termios t{};
    if (::tcgetattr(fd_, &t) != 0) {
      const int e = errno;
      close();
      return fail(errc::bad_state, e, "not a serial port");
    }
    apply(s, t);
    if (is_pseudo_terminal()) {
      // A pseudo-terminal has no line: Linux forces 8 data bits without parity on it, and some
      // kernels refuse a later request for anything else (EINVAL). Ask for what it does.
      t.c_cflag = (t.c_cflag & ~static_cast<tcflag_t>(CSIZE | PARENB | PARODD)) | CS8;
      t.c_iflag &= ~static_cast<tcflag_t>(INPCK);
    }
    if (::tcsetattr(fd_, TCSANOW, &t) != 0) {
      const int e = errno;
      close();
      return fail(errc::bad_state, e, "line settings refused");
    }
    return {};
  }

  /// A Unix 98 pseudo-terminal slave (device major 136..143).
  [[nodiscard]] bool is_pseudo_terminal() const noexcept {
    struct stat st {};
    if (::fstat(fd_, &st) != 0 || !S_ISCHR(st.st_mode)) return false;
    const unsigned major = ::major(st.st_rdev);
    return major >= 136U && major <= 143U;
  }

  errc fail(errc code, int sys_errno, std::string_view what) {
    bus_error e;
    e.code = code;
    e.sys_errno = sys_errno;
    e.what = name_ + ": " + std::string(what);
    if (sys_errno != 0) {
      e.what += ": ";
      e.what += std::strerror(sys_errno);
    }
    error_ = std::move(e);
    return code;
  }

  int fd_ = -1;
  std::string name_;
  bus_error error_{};
};

} // namespace fieldcodec::host

#endif // FIELDCODEC_HAS_TERMIOS
