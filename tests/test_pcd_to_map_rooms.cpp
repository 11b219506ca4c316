// pcd-to-map's rooms step on its own (apps/pcd-to-map/rooms_outputs): the objects extracted again
// without their stray returns lose those lying on the pieces the rooms step took for wall.
#include <gtest/gtest.h>

#include "rooms_outputs.hpp"
#include "test_support.hpp"

using namespace indoormap;

namespace {

// One row of 10 cells. The second extraction's objects: 1 on cells 0-3, 2 on cells 4-7, 3 on
// cells 8-9. The first extraction's pieces (`pieces`): 5 on cells 0-2 and 8, 6 on cell 3, 7 on
// cells 4-5, 8 on cells 6-7 and 9. The rooms step dropped piece 5 as an inner wall and piece 7
// as lying in a wall.
struct SecondPass {
  objects::ObjectsResult objs;
  Grid<std::int32_t> pieces{10, 1, 0};
  app::StoreyRooms rooms;
  SecondPass() {
    objs.labels = Grid<std::int32_t>(10, 1, 0);
    const int first_cell[] = {0, 4, 8, 10};
    for (int id = 1; id <= 3; ++id) {
      objects::FurnitureObject o;
      o.id = id;
      o.cells = first_cell[id] - first_cell[id - 1];
      for (int c = first_cell[id - 1]; c < first_cell[id]; ++c) objs.labels.at(c, 0) = id;
      objs.objects.push_back(o);
    }
    const int piece_of[] = {5, 5, 5, 6, 7, 7, 8, 8, 5, 8};
    for (int c = 0; c < 10; ++c) pieces.at(c, 0) = piece_of[c];
    rooms.inner_walls = {5};
    rooms.wall_pieces = {7};
  }
  std::vector<int> ids() const {
    std::vector<int> out;
    for (const auto& o : objs.objects) out.push_back(o.id);
    return out;
  }
};

}  // namespace

TEST(PcdToMapRooms, AnObjectHalfOnDroppedPiecesLeavesAndTheOthersKeepTheirIds) {
  SecondPass s;
  app::remove_objects_on(s.objs, s.pieces, s.rooms);
  // 1: three of its four cells on piece 5; 2: two of four on piece 7 (half is enough);
  // 3: one of two on piece 5 (half) - all three leave ...
  EXPECT_EQ(s.ids(), std::vector<int>{});
  // ... and with the wall pieces kept, 1 (3 of 4 on the inner wall) and 3 (1 of 2) leave, 2 stays.
  SecondPass t;
  t.rooms.wall_pieces.clear();
  app::remove_objects_on(t.objs, t.pieces, t.rooms);
  EXPECT_EQ(t.ids(), std::vector<int>{2});
  for (int c = 0; c < 10; ++c)
    EXPECT_EQ(t.objs.labels.at(c, 0), c >= 4 && c < 8 ? 2 : 0) << "cell " << c;
}

TEST(PcdToMapRooms, AnObjectMostlyOnKeptPiecesStays) {
  SecondPass s;
  s.rooms.inner_walls.clear();  // only piece 7 (cells 4-5 of object 2's four) was dropped
  s.pieces.at(5, 0) = 8;        // now one cell of four: under half
  app::remove_objects_on(s.objs, s.pieces, s.rooms);
  EXPECT_EQ(s.ids(), (std::vector<int>{1, 2, 3}));
}

TEST(PcdToMapRooms, NothingLeavesWhenNothingWasDroppedOrThePiecesDoNotFit) {
  SecondPass s;
  s.rooms.inner_walls.clear();
  s.rooms.wall_pieces.clear();
  app::remove_objects_on(s.objs, s.pieces, s.rooms);
  EXPECT_EQ(s.ids(), (std::vector<int>{1, 2, 3}));
  SecondPass t;
  t.pieces = Grid<std::int32_t>(9, 1, 5);  // another grid: no cell can be matched
  app::remove_objects_on(t.objs, t.pieces, t.rooms);
  EXPECT_EQ(t.ids(), (std::vector<int>{1, 2, 3}));
}
