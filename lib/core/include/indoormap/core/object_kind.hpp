#pragma once
// What a listed object of a room is. The names are part of the file formats (objects.json,
// objects.csv, the legend of objects.png) and read back by map-eval.
#include <array>
#include <optional>
#include <string_view>

namespace indoormap {

enum class ObjectKind {
  kFurniture,     ///< stands on or near the floor (a connected component of the furniture class)
  kHanging,       ///< in the furniture band, well above the floor (a wall cupboard, a low lamp)
  kLamp,          ///< above the furniture band, below the ceiling
  kPillar,        ///< a free-standing wall-class component
  kColumn,        ///< border analysis: a closed ring inside the room (seen all round)
  kInstallation,  ///< border analysis: an interior component that is not a closed ring
};

/// Every kind, in declaration order.
inline constexpr std::array<ObjectKind, 6> kObjectKinds = {
    ObjectKind::kFurniture, ObjectKind::kHanging, ObjectKind::kLamp,
    ObjectKind::kPillar,    ObjectKind::kColumn,  ObjectKind::kInstallation};

inline constexpr std::string_view to_string(ObjectKind k) {
  switch (k) {
    case ObjectKind::kFurniture:
      return "furniture";
    case ObjectKind::kHanging:
      return "hanging";
    case ObjectKind::kLamp:
      return "lamp";
    case ObjectKind::kPillar:
      return "pillar";
    case ObjectKind::kColumn:
      return "column";
    case ObjectKind::kInstallation:
      return "installation";
  }
  return "invalid";
}

/// The kind named s ("furniture", "hanging", ...); nullopt for any other string.
inline constexpr std::optional<ObjectKind> parse_object_kind(std::string_view s) {
  for (const ObjectKind k : kObjectKinds)
    if (to_string(k) == s) return k;
  return std::nullopt;
}

/// False for the kinds that do not stand on the floor (hanging, lamp): map-eval leaves them out
/// unless asked to include hanging items.
inline constexpr bool stands_on_floor(ObjectKind k) {
  return k != ObjectKind::kHanging && k != ObjectKind::kLamp;
}

}  // namespace indoormap
