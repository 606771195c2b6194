#pragma once
// The water in each pipe as a CalculiX fluid network, appended to the mesh's .inp, and the
// wall faces' forced convection to it in "<stem>.films.inp" beside the .inp.
//
// Per pipe (MeshDescription::pipes, stations from the first end; reversed for --reverse-flow):
//   water nodes on the centre line: a temperature node every kStationsPerSegment stations (the
//   last segment takes the remainder), a mass-flow node at the station halfway between, and one
//   more at each end for the inlet and outlet elements
//   *ELEMENT, TYPE=D          (0, m_in, T_0), (T_j, m_j, T_j+1) ..., (T_last, m_out, 0):
//                             CalculiX's three-node network elements, end nodes carry the water
//                             temperature (DOF 11), the middle one the mass flow (DOF 1)
//   ELSET pipe_<k>_water, NSET pipe_<k>_water (every node of it), NSET pipe_<k>_water_in /
//   _water_out (T_0, T_last), NSET pipe_<k>_water_flow (the mass-flow nodes, for *BOUNDARY on
//   DOF 1), and ELSET / NSET WATER over all pipes. Labels follow the mesh's: the network is in
//   neither EALL nor NALL.
// The films file: one "*FILM" line per wall face, "element, F<s>FC, T_j+1, h": a face between
// stations of segment j gives its heat to the segment's downstream node, so the water's
// m c_p (T_out - T_in) equals the heat through the walls exactly.
#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "engine/io/abaqus_names.hpp"
#include "engine/io/atomic_file.hpp"
#include "engine/io/boundary_cell_faces.hpp"
#include "engine/io/mesh_io.hpp"

namespace tubemesh::io {

inline constexpr int kStationsPerSegment = 2;

// "dam.inp" -> "dam.films.inp"
std::filesystem::path films_path(const std::filesystem::path& inp);

// What the mesh part of the .inp has used: labels and set names, the zero for coordinates.
struct InpNumbering {
    std::uint64_t nodes = 0, elements = 0;  // labels 1..nodes, 1..elements are taken
    AbaqusLabels& element_sets;
    AbaqusLabels& node_sets;
    double zero_below = 0;
};

// Writes the networks to `inp` (after the mesh part) and the films to `films` (comments alone
// for a mesh without pipes). Throws tubemesh::Error when there is no description (a mesh read
// from a file), --reverse-flow names no pipe, or a wall face lies between no two stations.
void write_pipe_networks(const HybridMesh& mesh, const std::array<std::vector<CellFaceRef>, kFaceKindCount>& owners,
                         const WriteOptions& options, InpNumbering numbering, AtomicFile& inp, AtomicFile& films);

}  // namespace tubemesh::io
