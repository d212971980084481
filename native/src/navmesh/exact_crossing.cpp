// Footfall — where two of the navigation mesh's constraints cross: computed
// with exact rationals, then rounded to doubles (navmesh_cdt.hpp says why).
#include <CGAL/Cartesian_converter.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Intersections_2/Segment_2_Segment_2.h>
#include <CGAL/Simple_cartesian.h>

#include "navmesh/navmesh_cdt.hpp"

namespace footfall {
namespace {

using Exact = CGAL::Simple_cartesian<CGAL::Exact_rational>;

Point rounded(const Exact::Point_2& p) { return {CGAL::to_double(p.x()), CGAL::to_double(p.y())}; }

using Crossing = boost::variant<Point, Kernel::Segment_2>;

}  // namespace

boost::optional<Crossing> CdtTraits::Intersect_2::operator()(const Segment& a,
                                                             const Segment& b) const {
  const CGAL::Cartesian_converter<Kernel, Exact> exact;
  const auto crossing = CGAL::intersection(exact(a), exact(b));
  if (!crossing) return boost::none;
  if (const auto* p = boost::get<Exact::Point_2>(&*crossing)) return Crossing(rounded(*p));
  const auto& overlap = boost::get<Exact::Segment_2>(*crossing);
  return Crossing(Segment(rounded(overlap.source()), rounded(overlap.target())));
}

}  // namespace footfall
