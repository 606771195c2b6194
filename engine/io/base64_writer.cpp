#include "engine/io/base64_writer.hpp"

namespace tubemesh::io {

namespace {

constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

}  // namespace

void Base64Writer::put_bytes(const void* data, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
        pending_[pending_count_++] = p[i];
        if (pending_count_ == 3) encode_pending();
    }
}

void Base64Writer::encode_pending() {
    if (text_used_ + 4 > sizeof text_) {
        out_.write_bytes(text_, text_used_);
        text_used_ = 0;
    }
    const unsigned v = (unsigned{pending_[0]} << 16) | (unsigned{pending_[1]} << 8) | unsigned{pending_[2]};
    text_[text_used_++] = kAlphabet[(v >> 18) & 63];
    text_[text_used_++] = kAlphabet[(v >> 12) & 63];
    text_[text_used_++] = pending_count_ > 1 ? kAlphabet[(v >> 6) & 63] : '=';
    text_[text_used_++] = pending_count_ > 2 ? kAlphabet[v & 63] : '=';
    pending_[0] = pending_[1] = pending_[2] = 0;
    pending_count_ = 0;
}

void Base64Writer::finish() {
    if (pending_count_ > 0) encode_pending();
    out_.write_bytes(text_, text_used_);
    text_used_ = 0;
}

}  // namespace tubemesh::io
