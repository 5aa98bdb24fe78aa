// genmesh/concepts.h — every graph concept genmesh algorithms are written against.
//
// One concept per header under concepts/genmesh/concepts/; each header's top
// comment is its table of valid expressions, and descriptor.h states the
// conventions that hold for all of them.
#pragma once

#include <genmesh/concepts/descriptor.h>
#include <genmesh/concepts/edge_list_graph.h>
#include <genmesh/concepts/face_graph.h>
#include <genmesh/concepts/face_list_graph.h>
#include <genmesh/concepts/halfedge_graph.h>
#include <genmesh/concepts/halfedge_list_graph.h>
#include <genmesh/concepts/local_operations.h>
#include <genmesh/concepts/mutable_face_graph.h>
#include <genmesh/concepts/mutable_halfedge_graph.h>
#include <genmesh/concepts/vertex_list_graph.h>
