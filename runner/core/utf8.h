// UTF-8 text read one code point at a time: for drawing labels (draw/font) and for refusing
// what JSON cannot hold (bench --json).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace pn {

// The code points of UTF-8 text; a malformed byte sequence becomes U+FFFD (one a byte).
std::vector<char32_t> decode_utf8(const std::string& utf8);

// Whether `text` is well-formed UTF-8: no malformed sequence, overlong form, surrogate or code
// point past U+10FFFF.
bool valid_utf8(const std::string& text);

}  // namespace pn
