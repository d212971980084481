// Footfall — built-in scenes: the demo, and the building blocks of the
// benchmark workloads and tests (walls with doors, boxes, a box field).
#pragma once

#include <cstdint>
#include <vector>

#include "footfall/crowd/scenario.hpp"
#include "footfall/ground/ground.hpp"

namespace footfall {

/// An axis-aligned box obstacle centred at `center`. [m]
Obstacle box_obstacle(Vec2 center, Vec2 size, double height = 1.0);

/// A wall along the line x = `x`, from y = -`half_length` to +`half_length`,
/// `thickness` thick, with a door of `door_width` centred at y = `door_center`. [m]
std::vector<Obstacle> wall_with_door(double x, double door_width, double door_center = 0.0,
                                     double half_length = 6.0, double thickness = 0.2);

/// The built-in demo: six characters through a 1.6 m doorway in a wall into
/// a cluttered room, and below the door two through narrow gaps in the wall,
/// one holding its arms in (0.55 m) and one side-stepping (0.42 m).
Scenario demo_scenario();

/// `count` random boxes of 0.5-1.5 m side in a square field of side `size`
/// centred on the origin, from a portable seeded generator (the same boxes on
/// every machine). [m]
std::vector<Obstacle> box_field(int count, double size, std::uint64_t seed);

/// The crowd workloads of the footstep paper's table 1, from seeded
/// generators; every agent leaves at its goal, as SteerSuite's do.
/// An egress: `agents` at random in a 10 x 10 m room, each leaving through
/// the 1.2 m door in its east wall to a point 7 m beyond it. Throws
/// std::invalid_argument if the room cannot hold them (so do the others).
Scenario egress_scenario(int agents, std::uint64_t seed);
/// A two-way hall 80 m long and `width` wide, open at both ends: half the
/// agents start in each half and leave by the far end. 16 m is the width of
/// SteerSuite's hallways (the paper's authors' own two-way hall of 200).
Scenario two_way_hall_scenario(int agents, std::uint64_t seed, double width = 16.0);
/// `agents` at random among `boxes` boxes in an 80 m field (box_field), each
/// walking 10-20 m in a random direction.
Scenario box_field_crowd_scenario(int agents, int boxes, std::uint64_t seed);

/// The blocks of a city: square blocks `kCityBlock` wide on a grid of streets
/// `kCityStreet` wide, filling the square of side `size` centred on the
/// origin (a multiple of kCityBlock + kCityStreet, the edge streets half as
/// wide). Throws std::invalid_argument for a size out of range. [m]
constexpr double kCityBlock = 6.0;
constexpr double kCityStreet = 4.0;
std::vector<Obstacle> city_blocks(double size);
/// The street area of such a city (the square less its blocks). [m^2]
double city_street_area(double size);
/// A busy city's streets: `agents` at random on the streets of a city of
/// side `size` (city_blocks), each walking to a random point of the
/// streets at least 20 m away in a straight line and leaving there, as
/// pedestrians crossing town in every direction do.
Scenario city_scenario(int agents, double size, std::uint64_t seed);

/// A flight of kStairsTreads treads kTreadDepth deep rising kRiser each,
/// kStairsWidth wide, from a floor at 0 (x from -8 to 0) to a landing (8 m
/// long) at its top; nothing beside them. `up` agents start on the floor
/// and climb to the landing, `down` start on the landing and go down, each
/// way two abreast on its right half, in rows 1 m apart, each to its own
/// goal 4-6 m past the flight (the first rows the furthest). [m]
constexpr int kStairsTreads = 6;
constexpr double kTreadDepth = 0.3, kRiser = 0.17, kStairsWidth = 3.0;
Scenario stairs_scenario(int up, int down);

/// A platform kPlatformHeight up (x from 4 to 10), too high to step onto,
/// beside a floor at 0 (x from -6 to 4), 8 m wide; a ramp 4 m long and 2 m
/// wide leads up to it along its edge (y 2-4). One walker crosses from the
/// floor to the platform. [m]
constexpr double kPlatformHeight = 0.6;
Scenario ramp_scenario();

/// A street at 0 (x from -12 to 12, y from -kStreetHalfWidth to
/// kStreetHalfWidth) between two banks kBridgeHeight up (y out to +-12),
/// their sides walls to the street; a footbridge's deck, 2 m wide and 0.2 m
/// thick, spans the street from bank to bank at x from -1 to 1, the street
/// passing under it; a flight of kBridgeRisers - 1 treads leads from the
/// street up into the north bank at x from 6 to 8. `under` agents walk along
/// the street under the deck, each way in turn (east on the south half);
/// `over` cross it from the south bank to the north, two abreast, in rows
/// 1 m apart. [m]
constexpr int kBridgeRisers = 17;
constexpr double kBridgeHeight = kBridgeRisers * kRiser, kStreetHalfWidth = 4.0;
Scenario bridge_scenario(int under, int over);

/// A height field of cells x cells squares of side `cell`, centred on the
/// origin, raised as a round hill `height` high whose slope spreads over
/// `spread` (a Gaussian of that deviation). [m]
GroundSurface hill_field(int cells, double cell, double height, double spread);
/// Two walkers crossing a hill 3 m high (hill_field(100, 0.3, 3, 5): 30 m
/// square, 20,000 triangles, slopes up to 20 degrees), 24 m each. [m]
Scenario hill_scenario();

}  // namespace footfall
