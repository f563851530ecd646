// The sampling kernels (sample.hpp's sample(), and the texture lookups of draw()), compiled
// once per ISA.
#include "../core/isa_build.hpp"

#include "sample_batch-inl.hpp"
#include "../core/isa_kernels.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

void sample(const detail::TextureDescription& texture, const SamplerOptions& options,
            const TextureQuery* queries, std::size_t count, Vec4* out) {
  using namespace sample_detail;
  sample_with<RecordQueries, RecordResults>(texture, options, queries, count, out);
}

void sample_fields(const detail::TextureDescription& texture, const SamplerOptions& options,
                   const detail::QueryFields& queries, std::size_t count,
                   const detail::ResultChannels& out) {
  using namespace sample_detail;
  sample_with<FieldQueries, ChannelResults>(texture, options, queries, count, out);
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
