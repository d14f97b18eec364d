#include "core/Gzip.h"

#include "core/Error.h"

#include <zlib.h>

#include <cstring>

namespace pb {

std::vector<unsigned char> gzipCompress(const void* data, std::size_t size) {
    z_stream z{};
    // windowBits 15 + 16: a gzip header (zlib writes no name and a zero time stamp), so the
    // same input gives the same bytes on every machine.
    if (deflateInit2(&z, Z_BEST_COMPRESSION, Z_DEFLATED, 15 + 16, 9, Z_DEFAULT_STRATEGY) != Z_OK)
        throw Error("gzip: zlib could not start");
    std::vector<unsigned char> out(deflateBound(&z, uLong(size)) + 32);
    z.next_in = static_cast<Bytef*>(const_cast<void*>(data));
    z.avail_in = uInt(size);
    z.next_out = out.data();
    z.avail_out = uInt(out.size());
    const int rc = deflate(&z, Z_FINISH);
    out.resize(z.total_out);
    deflateEnd(&z);
    if (rc != Z_STREAM_END) throw Error("gzip: compression did not finish");
    return out;
}

std::vector<unsigned char> gzipDecompress(const std::vector<unsigned char>& gz,
                                          const std::string& what) {
    if (gz.size() < 18 || gz[0] != 0x1f || gz[1] != 0x8b)
        throw Error(what + ": not a gzip stream");
    z_stream z{};
    if (inflateInit2(&z, 15 + 16) != Z_OK) throw Error(what + ": zlib could not start");
    std::vector<unsigned char> out;
    unsigned char chunk[1 << 16];
    z.next_in = const_cast<Bytef*>(gz.data());
    z.avail_in = uInt(gz.size());
    int rc = Z_OK;
    while (rc != Z_STREAM_END) {
        z.next_out = chunk;
        z.avail_out = sizeof chunk;
        rc = inflate(&z, Z_NO_FLUSH);
        if (rc != Z_OK && rc != Z_STREAM_END) break;
        out.insert(out.end(), chunk, chunk + (sizeof chunk - z.avail_out));
        if (rc == Z_OK && z.avail_in == 0 && z.avail_out != 0) break; // input ran out early
    }
    inflateEnd(&z);
    if (rc != Z_STREAM_END) throw Error(what + ": truncated or corrupt gzip data");
    return out;
}

} // namespace pb
