// fieldcodec CLI — the subcommands. run() is the whole program; main() only passes argv and
// the standard streams, so the tests call run() directly.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace fieldcodec::cli {

/// Exit codes (docs/cli.md, "Exit codes").
enum exit_code : int {
  exit_ok = 0,
  exit_failed = 1,    ///< the device refused or did not answer: SDO abort, timeout, QUIT ≠ 0
  exit_usage = 2,     ///< bad command line
  exit_io = 3,        ///< a file, interface or port could not be used, or the bus failed
  exit_input = 4,     ///< decode: some input could not be decoded (malformed, truncated)
  exit_dictionary = 5 ///< a dictionary could not be read
};

/// Runs `fieldcodec ARGS...` (args without the program name). `err_terminal`: `err` is a
/// terminal (progress lines are kept on one line there).
int run(const std::vector<std::string> &args, std::istream &in, std::ostream &out,
        std::ostream &err, bool err_terminal = false);

} // namespace fieldcodec::cli
