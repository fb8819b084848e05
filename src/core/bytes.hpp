#pragma once
/// A byte string built from and read back into numbers and text, for the history cache's
/// entries and keys. Numbers are stored as their exact bits (little-endian as the machine
/// holds them), so a value read back is the value written, bit for bit.
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace freestand::core {

class ByteWriter {
  public:
    void u64(std::uint64_t v) { raw(&v, sizeof v); }
    void i64(std::int64_t v) { raw(&v, sizeof v); }
    void f64(double v) { raw(&v, sizeof v); }
    void flag(bool v) { u64(v ? 1 : 0); }
    void text(std::string_view s) {
        u64(s.size());
        bytes_.append(s.data(), s.size());
    }
    void f64s(const std::vector<double>& v) {
        u64(v.size());
        raw(v.data(), v.size() * sizeof(double));
    }
    void opt_f64(const std::optional<double>& v) {
        flag(v.has_value());
        if (v) f64(*v);
    }
    const std::string& bytes() const { return bytes_; }
    std::string take() { return std::move(bytes_); }

  private:
    void raw(const void* p, std::size_t n) { bytes_.append(static_cast<const char*>(p), n); }
    std::string bytes_;
};

/// Reads what a ByteWriter wrote. Every read past the end, or a length beyond what is left,
/// sets failed() and returns zeros or empty values: a truncated or damaged entry is detected
/// by failed() and by at_end(), never by reading outside the buffer.
class ByteReader {
  public:
    explicit ByteReader(std::string_view bytes) : bytes_(bytes) {}

    std::uint64_t u64() { return scalar<std::uint64_t>(); }
    std::int64_t i64() { return scalar<std::int64_t>(); }
    double f64() { return scalar<double>(); }
    bool flag() { return u64() != 0; }
    std::string text() {
        const std::uint64_t n = u64();
        if (n > left()) return fail<std::string>();
        std::string s(bytes_.substr(pos_, n));
        pos_ += n;
        return s;
    }
    std::vector<double> f64s() {
        const std::uint64_t n = u64();
        if (n > left() / sizeof(double)) return fail<std::vector<double>>();
        std::vector<double> v(n);
        std::memcpy(v.data(), bytes_.data() + pos_, n * sizeof(double));
        pos_ += n * sizeof(double);
        return v;
    }
    std::optional<double> opt_f64() {
        if (!flag()) return std::nullopt;
        return f64();
    }
    bool failed() const { return failed_; }
    bool at_end() const { return pos_ == bytes_.size(); }

  private:
    std::size_t left() const { return bytes_.size() - pos_; }
    template <class T>
    T fail() {
        failed_ = true;
        pos_ = bytes_.size();
        return T{};
    }
    template <class T>
    T scalar() {
        if (left() < sizeof(T)) return fail<T>();
        T v;
        std::memcpy(&v, bytes_.data() + pos_, sizeof v);
        pos_ += sizeof v;
        return v;
    }

    std::string_view bytes_;
    std::size_t pos_ = 0;
    bool failed_ = false;
};

}  // namespace freestand::core
