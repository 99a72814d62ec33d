// Generator benchmark (not a test): parse a ~300 kB DCF and emit its header.
//
//   cmake -S . -B build-bench -G Ninja -DCMAKE_BUILD_TYPE=Release
//   cmake --build build-bench --target fieldcodec_gen_bench
//   ./build-bench/codegen/fieldcodec_gen_bench [target-bytes] [runs]
//   ./build-bench/codegen/fieldcodec_gen_bench [target-bytes] --dcf FILE   (write the DCF, exit)
//
// The DCF is generated deterministically in memory: CiA 301 communication objects, PDO
// parameters and a manufacturer area of VAR, ARRAY and RECORD objects with ParameterValue,
// Denotation, $NODEID defaults, CompactSubObj, comments and CRLF line ends — the mix of
// real vendor DCFs. Prints the size, the best and the median time of `runs` runs.
#include "readers.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

std::string hex4(unsigned v) {
  char b[8];
  std::snprintf(b, sizeof b, "%04X", v & 0xFFFFU);
  return b;
}

void var(std::string &o, const std::string &sec, const std::string &name, unsigned type,
         const char *access, const std::string &def, bool value) {
  o += "[" + sec + "]\r\nParameterName=" + name + "\r\nObjectType=0x7\r\nDataType=0x" + hex4(type) +
       "\r\nAccessType=" + access + "\r\nDefaultValue=" + def + "\r\nPDOMapping=0\r\n";
  if (value) o += "ParameterValue=" + def + "\r\nDenotation=" + name + " (configured)\r\n";
  o += "\r\n";
}

std::string make_dcf(std::size_t target) {
  std::string o;
  o.reserve(target + 4096);
  o += "; benchmark DCF written by fieldcodec_gen_bench\r\n[FileInfo]\r\nFileName=bench.dcf\r\n"
       "FileVersion=1\r\nFileRevision=1\r\nEDSVersion=4.0\r\nDescription=benchmark\r\n\r\n"
       "[DeviceInfo]\r\nVendorName=bench\r\nProductName=bench\r\nNrOfRXPDO=4\r\nNrOfTXPDO=4\r\n\r\n"
       "[DeviceComissioning]\r\nNodeID=3\r\nNodeName=bench\r\nBaudrate=500\r\n\r\n";
  std::vector<std::string> objects;
  std::string body;
  auto record = [&](unsigned index, const std::string &name, unsigned subs, unsigned type) {
    objects.push_back(hex4(index));
    body += "[" + hex4(index) + "]\r\nParameterName=" + name +
            "\r\nObjectType=0x9\r\nSubNumber=" + std::to_string(subs + 1U) + "\r\n\r\n";
    var(body, hex4(index) + "sub0", "Highest sub-index supported", 0x5, "ro", std::to_string(subs),
        false);
    for (unsigned s = 1; s <= subs; ++s) {
      var(body, hex4(index) + "sub" + std::to_string(s), name + " entry " + std::to_string(s), type,
          "rw", s % 3U == 0U ? "$NODEID+0x" + hex4(0x180U + s) : "0x" + hex4(s * 37U), true);
    }
  };
  objects.push_back("1000");
  var(body, "1000", "Device type", 0x7, "ro", "0x00020192", false);
  objects.push_back("1001");
  var(body, "1001", "Error register", 0x5, "ro", "0", false);
  record(0x1018, "Identity object", 4, 0x7);
  for (unsigned p = 0; p < 4; ++p) {
    record(0x1400 + p, "RPDO communication parameter " + std::to_string(p + 1U), 5, 0x7);
    record(0x1600 + p, "RPDO mapping parameter " + std::to_string(p + 1U), 8, 0x7);
    record(0x1800 + p, "TPDO communication parameter " + std::to_string(p + 1U), 6, 0x7);
    record(0x1A00 + p, "TPDO mapping parameter " + std::to_string(p + 1U), 8, 0x7);
  }
  static constexpr unsigned types[] = {0x3, 0x4, 0x6, 0x7, 0x8, 0x2, 0x5};
  unsigned index = 0x2000;
  while (o.size() + body.size() < target) {
    const unsigned k = index - 0x2000U;
    if (k % 10U == 9U) {
      objects.push_back(hex4(index));
      body += "[" + hex4(index) + "]\r\nParameterName=Compact array " + std::to_string(k) +
              "\r\nObjectType=0x8\r\nDataType=0x0006\r\nAccessType=rw\r\nDefaultValue=7\r\n"
              "PDOMapping=1\r\nCompactSubObj=8\r\n\r\n";
    } else if (k % 4U == 3U) {
      record(index, "Vendor record " + std::to_string(k), 6, types[k % 7U]);
    } else {
      objects.push_back(hex4(index));
      const unsigned t = types[k % 7U];
      var(body, hex4(index), "Vendor parameter " + std::to_string(k), t, k % 2U ? "rw" : "ro",
          t == 0x8                             ? "1.25"
          : (t == 0x3 || t == 0x4 || t == 0x2) ? "-" + std::to_string(k % 100U)
                                               : std::to_string(k * 3U),
          true);
    }
    ++index;
  }
  o += "[MandatoryObjects]\r\nSupportedObjects=2\r\n1=0x1000\r\n2=0x1018\r\n\r\n";
  o += "[OptionalObjects]\r\nSupportedObjects=" + std::to_string(objects.size() - 2U) + "\r\n";
  std::size_t n = 0;
  for (const auto &x : objects) {
    if (x == "1000" || x == "1018") continue;
    o += std::to_string(++n) + "=0x" + x + "\r\n";
  }
  o += "\r\n" + body;
  return o;
}

} // namespace

int main(int argc, char **argv) {
  const std::size_t target = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 300000U;
  const std::string dcf = make_dcf(target);
  if (argc > 3 && std::string(argv[2]) == "--dcf") { // the input of the header compile-time test
    std::FILE *f = std::fopen(argv[3], "wb");
    if (f == nullptr || std::fwrite(dcf.data(), 1, dcf.size(), f) != dcf.size()) return 1;
    return std::fclose(f) == 0 ? 0 : 1;
  }
  const int runs = argc > 2 ? std::atoi(argv[2]) : 50;
  std::vector<double> ms;
  std::vector<double> parse_ms;
  std::size_t header_bytes = 0;
  std::size_t entries = 0;
  for (int r = 0; r < runs; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    fieldcodec::gen::diagnostics diag;
    auto d = fieldcodec::gen::read_eds(dcf, "bench.dcf", diag);
    if (!d) {
      for (const auto &x : diag.all())
        std::fprintf(stderr, "%s\n", fieldcodec::gen::diagnostics::format(x).c_str());
      return 1;
    }
    d->source_name = "bench.dcf";
    d->stem = "bench";
    const auto tp = std::chrono::steady_clock::now();
    const std::string h = fieldcodec::gen::emit_header(*d);
    const auto t1 = std::chrono::steady_clock::now();
    ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    parse_ms.push_back(std::chrono::duration<double, std::milli>(tp - t0).count());
    header_bytes = h.size();
    entries = d->entries.size();
  }
  std::sort(ms.begin(), ms.end());
  std::sort(parse_ms.begin(), parse_ms.end());
  std::printf(
      "DCF %zu bytes, %zu entries -> header %zu bytes; parse+emit over %d runs: best %.2f ms, "
      "median %.2f ms (of which parsing: best %.2f ms, median %.2f ms)\n",
      dcf.size(), entries, header_bytes, runs, ms.front(), ms[ms.size() / 2U], parse_ms.front(),
      parse_ms[parse_ms.size() / 2U]);
  return 0;
}
