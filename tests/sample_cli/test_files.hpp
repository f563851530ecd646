// The files a test hands to edgewise-sample and the results it reads back.
#pragma once

#include <OpenImageIO/typedesc.h>

#include <span>
#include <string>
#include <vector>

#include "edgewise/sample.hpp"
#include "edgewise/vector.hpp"

namespace edgewise::sample_cli_test {

// Writes `pixels` (width x height x channels values of `type`, row-major) as stored: alpha is
// marked unassociated, so that no format premultiplies or divides it on the way. Throws
// std::runtime_error when OpenImageIO cannot write the file.
void write_image(const std::string& path, int width, int height, int channels, OIIO::TypeDesc type,
                 const void* pixels);

void write_queries(const std::string& path, std::span<const TextureQuery> queries);
void write_bytes(const std::string& path, const std::string& bytes);

// The result file as RGBA records; a size that is not whole records fails the test.
std::vector<Vec4> read_results(const std::string& path);

}  // namespace edgewise::sample_cli_test
