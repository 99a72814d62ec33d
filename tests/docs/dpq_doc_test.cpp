// The C++ block of docs/dpq.md ("Scaling"), as written there; its results are static_asserts.
// tests/docs_check/run.cmake fails when the page's block and this copy differ.
#include <fieldcodec/dictionaries/dpq_parameters.hpp>
#include <fieldcodec/dpq/parameter.hpp>

// clang-format off
namespace doc_dpq {
namespace p = fieldcodec::dictionaries::dpq_parameters; // generated from the CSV
namespace dpq = fieldcodec::dpq;

// Inj. P Limit 1, 4.0 bar at scale 327.67 → raw 1311 (od::descriptor does the scaling)
static_assert(p::inj_p_limit_1.to_raw(4.0).value() == 1311);
// … as the 4 bytes of the parameter's field, LSB first: 1F 05 00 00
constexpr auto bytes = dpq::to_bytes(p::inj_p_limit_1, 4.0).value();
static_assert(bytes.size == 4 && bytes.bytes[0] == 0x1F && bytes.bytes[1] == 0x05);
// read back exactly, at the places that round-trip (327.67 → 3): 4.001 bar
static_assert(dpq::from_bytes(p::inj_p_limit_1, bytes.span()).value().mantissa == 4001);
// the program status is read-only: nothing to send
static_assert(dpq::write_bytes(p::program_status, 1.0).is(fieldcodec::errc::access_denied));
} // namespace doc_dpq
// clang-format on
