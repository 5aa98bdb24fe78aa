// genmesh/validity.h — checks of halfedge meshes and polygon soups, and soup
// repair: includes <genmesh/mesh_check.h> (check_mesh), <genmesh/soup_check.h>
// (check_soup) and <genmesh/soup_repair.h> (repair_soup).
#pragma once

#include <genmesh/mesh_check.h>
#include <genmesh/soup_check.h>
#include <genmesh/soup_repair.h>
