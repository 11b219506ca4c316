#pragma once
// The scene turned into solids the ray caster can hit, and the ray caster itself.
//
// Solids are vertical convex prisms (walls, boxes, table tops, legs) and vertical cylinders (bins,
// pillars, cords, round tops). Walls are each room edge extruded outward by the wall thickness
// (mitred at the corners) from the floor to just above the room's highest ceiling point; doors
// and windows cut the wall pieces that hold them (the piece over a door, between the door top and
// the wall top, stays: the lintel). Floors (z = 0) and ceilings are "caps": a plane limited to a
// room polygon, or to a door's cut-out footprint (floor only).
#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

#include "indoormap/core/polygon.hpp"
#include "indoormap/sim/scene.hpp"

namespace indoormap::sim {

struct Solid {
  enum class Shape { kPrism, kCylinder };
  Shape shape = Shape::kPrism;
  Polygon footprint;  ///< prism: convex, counter-clockwise; cylinder: its 32-gon (for pictures)
  Eigen::Vector2d center_m = Eigen::Vector2d::Zero();  ///< cylinder
  double radius_m = 0.0;                               ///< cylinder
  double z0_m = 0.0, z1_m = 0.0;
  int furniture = -1;  ///< index into Scene::furniture; -1 for a wall piece
  int room = -1;       ///< wall piece: the room whose edge it extrudes
};

/// A horizontal floor (z = 0) and / or a ceiling plane z = a + g . (x, y), over a polygon.
struct Cap {
  Polygon polygon;
  bool floor = true;
  bool ceiling = true;
  double ceiling_a = 0.0;
  Eigen::Vector2d ceiling_g = Eigen::Vector2d::Zero();
  int room = -1;
};

struct SceneGeometry {
  std::vector<Solid> solids;         ///< wall pieces first, then furniture parts
  std::vector<Cap> caps;             ///< room floors / ceilings, then door floors
  std::vector<Polygon> door_floors;  ///< footprints cut out of walls by doors (free space)
};

/// Builds the solids of a scene (normalised with normalised(); checked with check_scene()).
SceneGeometry build_geometry(const Scene& scene);

/// The solids of one furniture item (index i of scene.furniture).
std::vector<Solid> furniture_solids(const Scene& scene, int i);

/// Ray casting against a SceneGeometry through a 2D uniform grid of primitive lists, traversed
/// with a DDA (Amanatides & Woo) and a mailbox so a primitive is tested once per ray.
/// Not thread-safe (the mailbox is state): use one RayCaster per thread.
class RayCaster {
 public:
  struct Hit {
    double t_m = 0.0;  ///< distance along the (unit) direction
    int solid = -1;    ///< index into SceneGeometry::solids, or -1 for a floor / ceiling
    int cap = -1;      ///< index into SceneGeometry::caps, or -1
  };

  /// cell_m: grid cell; enlarged automatically so the grid stays below ~4 M cells.
  explicit RayCaster(const SceneGeometry& geometry, double cell_m = 0.5);

  /// First surface along origin + t * dir for 0 < t <= t_max (dir must be unit length).
  /// Surfaces are seen from both sides; a ray starting inside a solid does not hit it.
  std::optional<Hit> cast(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, double t_max);

  int grid_width() const { return width_; }
  int grid_height() const { return height_; }

 private:
  struct Prim {
    std::uint8_t kind = 0;  // 0 prism, 1 cylinder, 2 cap
    std::uint8_t n = 0;     // prism edge count
    int index = 0;          // solid or cap index
    double z0 = 0, z1 = 0;
    double cx = 0, cy = 0, r = 0;                // cylinder
    double nx[8] = {}, ny[8] = {}, off[8] = {};  // prism half-planes nx*x + ny*y <= off
  };
  double intersect(const Prim& p, const Eigen::Vector3d& o, const Eigen::Vector3d& d) const;

  std::vector<Cap> caps_;
  std::vector<Prim> prims_;
  std::vector<std::uint32_t> cell_begin_;  // CSR: prims of cell k in items_[begin[k], begin[k+1])
  std::vector<std::uint32_t> items_;
  std::vector<std::uint32_t> mailbox_;
  std::uint32_t ray_id_ = 0;
  Eigen::Vector2d lo_ = Eigen::Vector2d::Zero();
  double cell_m_ = 0.5;
  int width_ = 0, height_ = 0;
};

}  // namespace indoormap::sim
