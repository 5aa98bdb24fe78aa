// genmesh/subdivision.h — every subdivision scheme: Loop, Catmull-Clark,
// midpoint (linear), √3, Doo-Sabin and modified butterfly.
//
// Each scheme is one function `<scheme>_subdivision(g, {options})` over any
// MutableFaceGraph with vertex points and vertex/halfedge index maps
// (genmesh::Halfedge_mesh, CGAL::Surface_mesh, ...), returning a
// genmesh::Subdivision_result {levels_done, vertices, faces}. Every level
// computes all new positions from the old mesh first, then refines the
// topology — in place for Loop, Catmull-Clark, butterfly and midpoint on
// triangles (detail/in_place.h), through a rebuilt mesh for √3, Doo-Sabin and
// midpoint on other faces (their levels do not keep the old edges, or mix
// two cuts) — numbered deterministically, so every backend gives the same
// mesh. See docs/subdivision.md.
#pragma once

#include <genmesh/subdivision/butterfly.h>
#include <genmesh/subdivision/catmull_clark.h>
#include <genmesh/subdivision/creases.h>
#include <genmesh/subdivision/doo_sabin.h>
#include <genmesh/subdivision/loop.h>
#include <genmesh/subdivision/midpoint.h>
#include <genmesh/subdivision/sqrt3.h>
