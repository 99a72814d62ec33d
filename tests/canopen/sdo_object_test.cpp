// SDO frames for dictionary entries (against the generated XENAX CAN dictionary).
#include <fieldcodec/canopen/sdo_object.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>

#include <doctest/doctest.h>

#include <cstdint>

namespace co = fieldcodec::canopen;
namespace sdo = fieldcodec::canopen::sdo;
namespace x = fieldcodec::dictionaries::xenax_canopen;
using fieldcodec::errc;

// XENAX 5.4.1: 6060h := 0xFF (-1, jog) on node 1.
static_assert(sdo::download(1, x::modes_of_operation_requested, -1).value() ==
              co::make_frame(0x601, {0x2F, 0x60, 0x60, 0x00, 0xFF, 0x00, 0x00, 0x00}).value());

TEST_CASE("typed SDO download and upload of dictionary entries") {
  CHECK(sdo::download(1, x::controlword, 0x0F).value() ==
        co::make_frame(0x601, {0x2B, 0x40, 0x60, 0x00, 0x0F, 0x00, 0x00, 0x00}).value());
  CHECK(sdo::download(1, x::target_position, -2).value() ==
        co::make_frame(0x601, {0x23, 0x7A, 0x60, 0x00, 0xFE, 0xFF, 0xFF, 0xFF}).value());
  CHECK(sdo::download(1, x::modes_of_operation_requested, 11) == errc::out_of_range);
  CHECK(sdo::download(1, x::modes_of_operation_requested, -3) == errc::out_of_range);
  CHECK(sdo::download(1, x::controlword, 70000) == errc::out_of_range); // limit 0..65535
  CHECK(sdo::download(1, x::statusword, 1) == errc::access_denied);
  CHECK(sdo::download(0, x::controlword, 1) == errc::invalid_argument);
  CHECK(sdo::download(1, x::manufacturer_device_name, 1) == errc::access_denied);
  CHECK(sdo::upload(1, x::statusword).value() ==
        co::make_frame(0x601, {0x40, 0x41, 0x60, 0x00, 0, 0, 0, 0}).value());
  const auto rsp = co::make_frame(0x581, {0x4B, 0x41, 0x60, 0x00, 0x37, 0x12, 0, 0}).value();
  CHECK(sdo::upload_value(x::statusword, rsp).value().to_uint64().value() == 0x1237);
  CHECK(sdo::upload_value(x::controlword, rsp) == errc::unexpected_frame); // other object
  const auto pos = co::make_frame(0x581, {0x43, 0x64, 0x60, 0x00, 0xFF, 0xFF, 0xFF, 0xFF}).value();
  CHECK(sdo::upload_value(x::position_actual_value, pos).value().to_int64().value() == -1);
  const auto wrong = co::make_frame(0x581, {0x4F, 0x41, 0x60, 0x00, 0x37, 0, 0, 0}).value();
  CHECK(sdo::upload_value(x::statusword, wrong) == errc::bad_length);
  const auto ab = co::make_frame(0x581, {0x80, 0x41, 0x60, 0x00, 0, 0, 2, 6}).value();
  CHECK(sdo::upload_value(x::statusword, ab) == errc::aborted);
  const auto seg = co::make_frame(0x581, {0x41, 0x41, 0x60, 0x00, 2, 0, 0, 0}).value();
  CHECK(sdo::upload_value(x::statusword, seg) == errc::unexpected_frame);
  const auto unsized = co::make_frame(0x581, {0x42, 0x41, 0x60, 0x00, 0x37, 0x12, 0, 0}).value();
  CHECK(sdo::upload_value(x::statusword, unsized).value().to_uint64().value() == 0x1237);
}
