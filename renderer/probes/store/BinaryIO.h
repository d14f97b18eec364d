#pragma once
// Little-endian byte writer and a bounds-checked reader for the probe file. The reader never
// reads past the end: a short or inconsistent file becomes a pb::Error naming the file.
#include "core/Error.h"

#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

namespace pb::probes {

static_assert(std::endian::native == std::endian::little, "probe files are little-endian");

class ByteWriter {
public:
    template <class T> void pod(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        raw(&v, sizeof(T));
    }
    void raw(const void* p, std::size_t n) {
        const auto* b = static_cast<const std::uint8_t*>(p);
        data_.insert(data_.end(), b, b + n);
    }
    void str(const std::string& s) {
        pod(std::uint32_t(s.size()));
        raw(s.data(), s.size());
    }
    std::vector<std::uint8_t>& data() { return data_; }

private:
    std::vector<std::uint8_t> data_;
};

class ByteReader {
public:
    ByteReader(const std::uint8_t* data, std::size_t size, std::string path)
        : data_(data), size_(size), path_(std::move(path)) {}
    template <class T> T pod(const char* what) {
        static_assert(std::is_trivially_copyable_v<T>);
        T v;
        std::memcpy(&v, take(sizeof(T), what), sizeof(T));
        return v;
    }
    const std::uint8_t* take(std::size_t n, const char* what) {
        if (n > size_ - pos_)
            throw fileError(path_, std::string("file is truncated or corrupt (reading ") + what +
                                       " at byte " + std::to_string(pos_) + ")");
        const std::uint8_t* p = data_ + pos_;
        pos_ += n;
        return p;
    }
    std::string str(const char* what, std::size_t maxLength = 4096) {
        auto n = pod<std::uint32_t>(what);
        if (n > maxLength)
            throw fileError(path_,
                            std::string("corrupt ") + what + " (length " + std::to_string(n) + ")");
        const std::uint8_t* p = take(n, what);
        return std::string(reinterpret_cast<const char*>(p), n);
    }
    std::size_t position() const { return pos_; }
    std::size_t remaining() const { return size_ - pos_; }

private:
    const std::uint8_t* data_;
    std::size_t size_, pos_ = 0;
    std::string path_;
};

} // namespace pb::probes
