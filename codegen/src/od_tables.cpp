// fieldcodec-gen — a dictionary read at run time as od tables.
#include "od_tables.hpp"

#include <fieldcodec/od/entry_spec.hpp>

#include <algorithm>

namespace fieldcodec::gen {

od::text od_tables::keep(std::string_view s) {
  if (s.empty()) return od::text{};
  texts_.emplace_back(s);
  return od::text{std::string_view(texts_.back())};
}

od_tables::od_tables(const dictionary &d, od_table_options o) {
  std::size_t n = 0;
  for (const entry &e : d.entries) n += e.count;
  entries_.reserve(n);
  infos_.reserve(n);
  scales_.reserve(n);
  display_names_.reserve(n);
  object_names_.reserve(n);
  for (const entry &e : d.entries) {
    for (std::uint16_t k = 0; k < e.count; ++k) {
      od::entry_spec x = spec_of(e);
      x.sub = static_cast<std::uint8_t>(e.sub + k);
      x.size =
          od::is_byte_string(e.type) && (e.size_declared || o.capacity_from_default) ? e.size : 0U;
      x.default_text = keep(e.default_text.str());
      std::string name = e.name;
      if (e.count > 1U) name += std::to_string(x.sub);
      od::entry_info info{};
      info.name = keep(name);
      info.unit = keep(e.unit.str());
      info.denotation = keep(e.denotation);
      info.parameter_value = e.parameter_value;
      info.parameter_text = keep(e.parameter_text.str());
      scaling::linear scale{};
      if (e.scaled) scale = scaling::linear{e.scale, e.offset};
      if (!o.units.empty()) {
        if (auto u = od::apply_unit(x, info.unit, scale, o.units)) {
          x = u.value().spec;
          info.unit = u.value().unit;
          scale = u.value().scale;
        } else {
          unit_failures_.push_back({x.index, x.sub});
        }
      }
      // the packed columns, in storage that stays where it is (texts_ is a deque)
      const char *extra = nullptr;
      if (const std::size_t bytes = od::packed_size(x); bytes != 0U) {
        std::string &packed = texts_.emplace_back(bytes, '\0');
        (void)od::pack(x, std::span<char>(packed.data(), packed.size()));
        extra = packed.data();
      }
      const auto obj = d.objects.find(e.index);
      const bool var =
          e.object == od::object_code::var || obj == d.objects.end() || obj->second.name.empty();
      object_names_.push_back(var ? std::string_view{} : keep(obj->second.name).view());
      if (var || obj->second.name == name) {
        display_names_.push_back(info.name.view());
      } else {
        display_names_.push_back(keep(obj->second.name + ": " + name).view());
      }
      entries_.push_back(od::make_entry(x, extra));
      infos_.push_back(info);
      scales_.push_back(scale);
    }
  }
}

result<od::address> od_tables::address_of(std::string_view object,
                                          std::string_view sub) const noexcept {
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    const bool var = object_names_[i].empty();
    if (var ? (sub.empty() && infos_[i].name.view() == object)
            : (object_names_[i] == object && infos_[i].name.view() == sub)) {
      return od::address{entries_[i].index, entries_[i].sub};
    }
  }
  return errc::unknown_object;
}

std::string_view od_tables::display_name(od::address a) const noexcept {
  const std::size_t i = view().position(a);
  return i < display_names_.size() ? display_names_[i] : std::string_view{};
}

} // namespace fieldcodec::gen
