// fieldcodec — the store a node works on (canopen/node/): what node::device needs of it.
#pragma once

#include <fieldcodec/canopen/node/values.hpp>
#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/address.hpp>
#include <fieldcodec/od/dictionary.hpp>

#include <concepts>
#include <cstdint>
#include <span>

namespace fieldcodec::canopen::node {

/// What the node (node::device) needs of a store: the canopen::object_store parts interface, plus
/// the application's own write (`set`: no access check, no write hook), the current value, the
/// dictionary, and restoring the power-on values of a range of objects (NMT resets).
/// canopen::dictionary_store is one.
template <class S>
concept node_store = canopen::object_store<S> &&
    requires(S &s, const S &cs, od::address a, std::span<const std::uint8_t> v, std::uint16_t i) {
  { s.set(a, v) } -> std::same_as<abort_code>;
  { cs.value(a) } -> std::same_as<result<std::span<const std::uint8_t>>>;
  { cs.dictionary() } -> std::same_as<od::dictionary>;
  { s.restore_defaults(i, i) } -> std::same_as<status>;
};

} // namespace fieldcodec::canopen::node
