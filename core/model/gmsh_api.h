// Gmsh's C API (gmshc.h), loaded the first time a scene needs a mesher.
//
// Linking libgmsh costs every process about 60 ms before main() (it pulls in
// some ninety libraries and their relocations; measured with an empty
// program), although only disks and cutting patterns need it: rectangles are
// meshed by our own code. So libgmsh is opened with dlopen on first use.
#pragma once

#include <cstddef>

namespace drape {

// The functions gmsh_mesher.cc calls; the signatures are gmshc.h's (Gmsh 4.8).
struct GmshApi {
  void (*Free)(void* p);
  void (*Initialize)(int argc, char** argv, int read_config_files, int* ierr);
  void (*Finalize)(int* ierr);
  void (*OptionSetNumber)(const char* name, double value, int* ierr);
  void (*ModelAdd)(const char* name, int* ierr);
  int (*GeoAddPoint)(double x, double y, double z, double mesh_size, int tag, int* ierr);
  int (*GeoAddLine)(int start, int end, int tag, int* ierr);
  int (*GeoAddCircleArc)(
      int start, int center, int end, int tag, double nx, double ny, double nz, int* ierr);
  int (*GeoAddCurveLoop)(int* curves, std::size_t n, int tag, int reorient, int* ierr);
  int (*GeoAddPlaneSurface)(int* wires, std::size_t n, int tag, int* ierr);
  void (*GeoMeshSetRecombine)(int dim, int tag, double angle, int* ierr);
  void (*GeoSynchronize)(int* ierr);
  void (*MeshEmbed)(int dim, int* tags, std::size_t tags_n, int in_dim, int in_tag, int* ierr);
  void (*MeshGenerate)(int dim, int* ierr);
  void (*MeshGetNodes)(std::size_t** tags,
                       std::size_t* tags_n,
                       double** coords,
                       std::size_t* coords_n,
                       double** parametric,
                       std::size_t* parametric_n,
                       int dim,
                       int tag,
                       int include_boundary,
                       int return_parametric,
                       int* ierr);
  void (*MeshGetElements)(int** types,
                          std::size_t* types_n,
                          std::size_t*** element_tags,
                          std::size_t** element_tags_n,
                          std::size_t* element_tags_nn,
                          std::size_t*** node_tags,
                          std::size_t** node_tags_n,
                          std::size_t* node_tags_nn,
                          int dim,
                          int tag,
                          int* ierr);
  void (*LoggerStart)(int* ierr);
  void (*LoggerGet)(char*** log, std::size_t* log_n, int* ierr);
  void (*LoggerStop)(int* ierr);
  void (*LoggerGetLastError)(char** error, int* ierr);
};

// The API, opened on the first call (thread-safe). Throws MeshError naming
// the library and dlopen's reason when it cannot be opened or lacks a
// function.
const GmshApi& Gmsh();

}  // namespace drape
