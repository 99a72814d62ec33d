// fieldcodec — command-line tool: decode CANopen and PA-CONTROL traffic, talk to devices.
#include "app.hpp"

#include <unistd.h>

#include <iostream>
#include <string>
#include <vector>

int main(int argc, char **argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  return fieldcodec::cli::run(args, std::cin, std::cout, std::cerr, ::isatty(STDERR_FILENO) != 0);
}
