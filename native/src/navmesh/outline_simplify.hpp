// Footfall — fewer vertices for a detailed obstacle outline, without letting
// anything through: the simplified polygon contains the original.
#pragma once

#include <vector>

#include "footfall/model/geometry.hpp"

namespace footfall {

/// Outlines with more vertices than this are simplified when they enter the
/// navigation mesh: a path query's cost grows steeply with the vertices of
/// one polygon (a smooth one turns the path at each of them).
constexpr std::size_t kSimplifyAbove = 32;
/// How far the simplified outline may lie outside the original. [m]
constexpr double kOutlineTolerance = 0.01;

/// A simple counter-clockwise polygon with as few vertices as greedy steps
/// find, that contains `ccw` (simple, counter-clockwise, at least 3 vertices)
/// and whose boundary lies within `tolerance` of its boundary. Each step
/// cuts a notch (drops a reflex vertex) or extends the two edges beside a
/// short edge to where they meet (two convex vertices become one), the least
/// outward step first, never one that would touch another part of the
/// outline. O(n log n) for outlines whose edges are about equally long.
std::vector<Vec2> simplify_outward(const std::vector<Vec2>& ccw, double tolerance);

}  // namespace footfall
