#include "core/model/gmsh_api.h"

#include <dlfcn.h>

#include <string>

#include "core/model/mesh.h"

namespace drape {
namespace {

// Where to look: the library CMake found, then its runtime names.
constexpr const char* kLibraries[] = {DRAPE_GMSH_LIBRARY, "libgmsh.so.4.8", "libgmsh.so"};

template <typename F>
void Bind(void* library, const char* name, F& function) {
  void* symbol = dlsym(library, name);
  if (!symbol)
    throw MeshError(std::string("Gmsh's library has no function ") + name + " (Gmsh 4.8 expected)");
  function = reinterpret_cast<F>(symbol);
}

GmshApi Load() {
  void* library = nullptr;
  std::string reasons;
  for (const char* name : kLibraries) {
    library = dlopen(name, RTLD_NOW | RTLD_LOCAL);
    if (library) break;
    const char* why = dlerror();
    reasons += std::string(reasons.empty() ? "" : "; ") + (why ? why : name);
  }
  if (!library)
    throw MeshError("cannot load Gmsh, which disks and polygons are meshed with (" + reasons +
                    "): install Debian's libgmsh-dev, or use a rectangle");
  GmshApi api{};
  Bind(library, "gmshFree", api.Free);
  Bind(library, "gmshInitialize", api.Initialize);
  Bind(library, "gmshFinalize", api.Finalize);
  Bind(library, "gmshOptionSetNumber", api.OptionSetNumber);
  Bind(library, "gmshModelAdd", api.ModelAdd);
  Bind(library, "gmshModelGeoAddPoint", api.GeoAddPoint);
  Bind(library, "gmshModelGeoAddLine", api.GeoAddLine);
  Bind(library, "gmshModelGeoAddCircleArc", api.GeoAddCircleArc);
  Bind(library, "gmshModelGeoAddCurveLoop", api.GeoAddCurveLoop);
  Bind(library, "gmshModelGeoAddPlaneSurface", api.GeoAddPlaneSurface);
  Bind(library, "gmshModelGeoMeshSetRecombine", api.GeoMeshSetRecombine);
  Bind(library, "gmshModelGeoSynchronize", api.GeoSynchronize);
  Bind(library, "gmshModelMeshEmbed", api.MeshEmbed);
  Bind(library, "gmshModelMeshGenerate", api.MeshGenerate);
  Bind(library, "gmshModelMeshGetNodes", api.MeshGetNodes);
  Bind(library, "gmshModelMeshGetElements", api.MeshGetElements);
  Bind(library, "gmshLoggerStart", api.LoggerStart);
  Bind(library, "gmshLoggerGet", api.LoggerGet);
  Bind(library, "gmshLoggerStop", api.LoggerStop);
  Bind(library, "gmshLoggerGetLastError", api.LoggerGetLastError);
  return api;  // the library stays open for the process
}

}  // namespace

const GmshApi& Gmsh() {
  static const GmshApi api = Load();  // a failed load throws, and is tried again next time
  return api;
}

}  // namespace drape
