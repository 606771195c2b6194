#pragma once
// Mesh files: Gmsh MSH 4.1 (ASCII and binary, read and write), VTK XML .vtu and .vtm
// multiblock and Abaqus / CalculiX .inp (write). Writers go through a temporary file and
// rename it, so a failure never leaves a partial mesh behind. Readers throw tubemesh::Error
// naming the line or byte offset.
#include <filesystem>
#include <vector>

#include "engine/mesh/hybrid_mesh.hpp"
#include "engine/mesh/mesh_description.hpp"

namespace tubemesh {

enum class MshEncoding { Ascii, Binary };

// The .inp element family: stress/displacement C3D4 / C3D8 (which CalculiX also uses for heat
// transfer), Abaqus heat transfer DC3D4 / DC3D8 (CalculiX reads them too), coupled
// temperature-displacement for CalculiX (C3D4 / C3D8: its *COUPLED TEMPERATURE-DISPLACEMENT
// step gives them the temperature degree of freedom; it has no C3D*T), or for Abaqus
// (C3D4T / C3D8T, which CalculiX refuses).
enum class InpFamily { Stress, HeatTransfer, Coupled, CoupledAbaqus };
// Pyramids in .inp: an 8-node brick with the apex repeated (nodes 1 2 3 4 5 5 5 5, faces
// numbered as the brick's: base S1, sides S3-S6), which CalculiX and every Abaqus version
// read; or the 5-node C3D5 (stress family only), for solvers that have it.
enum class InpPyramid { CollapsedHex, C3D5 };

// The water in every pipe as a CalculiX fluid network in the .inp, its *FILM lines in a file
// beside it (engine/io/inp_network.hpp). Needs MeshDescription::pipes.
struct PipeNetworkOptions {
    bool write = false;
    // h of every wall face's forced convection, in the deck's units: 2000 W/(m2 K) is water at
    // about 0.5 m/s in a 25 mm pipe (Dittus-Boelter); a plastic pipe's wall lowers it.
    double film_coefficient = 2000;
    std::vector<int> reverse_flow;  // pipe numbers k (pipe_<k>) whose water enters at the second end
};

struct WriteOptions {
    MshEncoding msh_encoding = MshEncoding::Binary;
    InpFamily inp_family = InpFamily::Stress;
    InpPyramid inp_pyramid = InpPyramid::CollapsedHex;
    // The length unit, the surface groups' CAD kinds and aliases, named node sets (rims), for
    // the files' comment blocks and extra sets. Null: the mesh alone.
    const MeshDescription* description = nullptr;
    PipeNetworkOptions pipe_network;
};

void write_msh(const HybridMesh& mesh, const std::filesystem::path& path, MshEncoding encoding = MshEncoding::Binary,
               const MeshDescription* description = nullptr);
HybridMesh read_msh(const std::filesystem::path& path);

// The volume cells (tets, pyramids, hexes) with their quality measures as cell data.
void write_vtu(const HybridMesh& mesh, const std::filesystem::path& path, const MeshDescription* description = nullptr);
// A multiblock: block "volume" with one .vtu per region, block "boundary" with one .vtu per
// surface group, each named after its group; the .vtu files go to a folder named after the
// .vtm file (dam.vtm -> dam/), as ParaView's own writer lays them out.
void write_vtm(const HybridMesh& mesh, const std::filesystem::path& path, const MeshDescription* description = nullptr);
void write_inp(const HybridMesh& mesh, const std::filesystem::path& path, const WriteOptions& options = {});

// By extension: .msh, .vtu, .vtm, .inp. Any other extension is an Error.
void write_mesh(const HybridMesh& mesh, const std::filesystem::path& path, const WriteOptions& options = {});

}  // namespace tubemesh
