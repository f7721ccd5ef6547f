// Threads for refinement (Options::threads). A WebAssembly build without pthreads has none
// (ACUTEMESH_THREADS undefined): its steps run one after another and make the same mesh.
#pragma once

#include "acutemesh/acutemesh.h"
#if !defined(__EMSCRIPTEN__) || defined(__EMSCRIPTEN_PTHREADS__)
#include <thread>
#define ACUTEMESH_THREADS 1
#endif

namespace acutemesh::detail {

#ifdef ACUTEMESH_THREADS
// The threads a run may use: Options::threads, 0 meaning one per hardware thread.
inline unsigned threadsFor(const Options& options) {
  return options.threads ? options.threads : std::thread::hardware_concurrency();
}
#endif

}  // namespace acutemesh::detail
