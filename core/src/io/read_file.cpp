// readInputFile: a file's text, read whole, to the parser its extension names.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <new>
#include <stdexcept>

#include "acutemesh/io.h"
#include "parse_context.h"
#include "triangle_format.h"

namespace acutemesh {
namespace {

using io::failure;

bool readWholeFile(const std::string& path, std::string& out, std::string& error) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) {
    error = path + ": cannot open (" + std::strerror(errno) + ")";
    return false;
  }
  // A first chunk, before trusting ftell (a directory opens, says LONG_MAX, then fails to
  // read); then the rest in one read when the size is known, in chunks otherwise (pipes).
  long size = -1;
  if (std::fseek(f, 0, SEEK_END) == 0) {
    size = std::ftell(f);
    if (std::fseek(f, 0, SEEK_SET) != 0) size = -1;
  }
  char buf[1 << 14];  // small: Emscripten's stack is small
  size_t got = std::fread(buf, 1, sizeof buf, f);
  out.assign(buf, got);
  if (got == sizeof buf && !std::ferror(f)) {
    if (size > static_cast<long>(got) && static_cast<unsigned long>(size) < out.max_size() / 2) {
      out.resize(static_cast<size_t>(size));
      const size_t have = std::fread(&out[got], 1, out.size() - got, f);
      out.resize(got + have);
    }
    do {
      got = std::fread(buf, 1, sizeof buf, f);
      out.append(buf, got);
    } while (got == sizeof buf);
  }
  const bool bad = std::ferror(f) != 0;
  const int err = errno;
  std::fclose(f);
  if (bad) {
    error = path + ": cannot read (" + std::strerror(err) + ")";
    return false;
  }
  return true;
}

std::string lowerExtension(const std::string& path) {
  const size_t slash = path.find_last_of("/\\");
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
  std::string ext = path.substr(dot);
  for (char& ch : ext)
    if (ch >= 'A' && ch <= 'Z') ch = static_cast<char>(ch - 'A' + 'a');
  return ext;
}

ParseResult readInputFileOrThrow(const std::string& path, Input& out) {
  const std::string ext = lowerExtension(path);
  if (ext != ".poly" && ext != ".node" && ext != ".json")
    return failure(path + ": expected the extension .poly, .node or .json, found " +
                   (ext.empty() ? std::string("none") : "'" + ext + "'"));
  std::string text, error;
  if (!readWholeFile(path, text, error)) return failure(std::move(error));
  if (ext == ".node") return parseNode(text, path, out);
  if (ext == ".json") return parseJson(text, path, out);
  if (io::polyHasNoVertices(text)) {
    const std::string nodePath = path.substr(0, path.size() - 5) + ".node";
    std::string nodeText;
    if (!readWholeFile(nodePath, nodeText, error)) return failure(std::move(error));
    return parsePoly(text, path, out, nodeText, nodePath);
  }
  return parsePoly(text, path, out);
}

}  // namespace

// A file larger than memory (or a parse of it) ends with a message, not an exception.
ParseResult readInputFile(const std::string& path, Input& out) {
#if defined(__cpp_exceptions) || defined(__EXCEPTIONS)
  try {
    return readInputFileOrThrow(path, out);
  } catch (const std::bad_alloc&) {
  } catch (const std::length_error&) {
  }
  return failure(path + ": out of memory reading it");
#else
  return readInputFileOrThrow(path, out);
#endif
}

ParseResult readSizeFile(const std::string& path, SizeField& out, std::vector<std::string>* warnings) {
  const std::string ext = lowerExtension(path);
  if (ext != ".json" && ext != ".node")
    return failure(path + ": expected a size file with the extension .json or .node, found " +
                   (ext.empty() ? std::string("none") : "'" + ext + "'"));
  std::string text, error;
  if (!readWholeFile(path, text, error)) return failure(std::move(error));
  return ext == ".node" ? parseSizeNode(text, path, out, warnings)
                        : parseSizeField(text, path, out, warnings);
}

}  // namespace acutemesh
