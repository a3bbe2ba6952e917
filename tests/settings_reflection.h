// The members of a settings struct, found without naming them: the number of its members (the most
// initializers it takes) and their byte ranges through a structured binding. The option-table tests
// use it to find settings members that no option row binds.
#pragma once
#include <cstddef>
#include <utility>
#include <vector>

namespace penumbra::test {

struct AnyInit {
    template <class T>
    operator T() const;
};

template <class T, class... A>
constexpr size_t memberCount() {
    if constexpr (requires { T{A{}..., AnyInit{}}; }) return memberCount<T, A..., AnyInit>();
    else return sizeof...(A);
}

template <class M>
std::pair<size_t, size_t> rangeOf(const void* base, const M& m) {
    const size_t offset = size_t(reinterpret_cast<const char*>(&m) - static_cast<const char*>(base));
    return {offset, offset + sizeof(M)};
}

// Byte ranges [first, second) of every member of `s`, in declaration order.
template <class T>
std::vector<std::pair<size_t, size_t>> memberRanges(const T& s) {
    constexpr size_t n = memberCount<T>();
    static_assert(n >= 1 && n <= 32, "memberRanges handles 1 to 32 members");
    if constexpr (n == 1) {
        const auto& [m0] = s;
        return {rangeOf(&s, m0)};
    } else if constexpr (n == 2) {
        const auto& [m0,m1] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1)};
    } else if constexpr (n == 3) {
        const auto& [m0,m1,m2] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1), rangeOf(&s, m2)};
    } else if constexpr (n == 4) {
        const auto& [m0,m1,m2,m3] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1), rangeOf(&s, m2), rangeOf(&s, m3)};
    } else if constexpr (n == 5) {
        const auto& [m0,m1,m2,m3,m4] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1), rangeOf(&s, m2), rangeOf(&s, m3), rangeOf(&s, m4)};
    } else if constexpr (n == 6) {
        const auto& [m0,m1,m2,m3,m4,m5] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1), rangeOf(&s, m2), rangeOf(&s, m3), rangeOf(&s, m4), rangeOf(&s, m5)};
    } else if constexpr (n == 7) {
        const auto& [m0,m1,m2,m3,m4,m5,m6] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1), rangeOf(&s, m2), rangeOf(&s, m3), rangeOf(&s, m4), rangeOf(&s, m5), rangeOf(&s, m6)};
    } else if constexpr (n == 8) {
        const auto& [m0,m1,m2,m3,m4,m5,m6,m7] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1), rangeOf(&s, m2), rangeOf(&s, m3), rangeOf(&s, m4), rangeOf(&s, m5), rangeOf(&s, m6), rangeOf(&s, m7)};
    } else if constexpr (n == 9) {
        const auto& [m0,m1,m2,m3,m4,m5,m6,m7,m8] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1), rangeOf(&s, m2), rangeOf(&s, m3), rangeOf(&s, m4), rangeOf(&s, m5), rangeOf(&s, m6), rangeOf(&s, m7), rangeOf(&s, m8)};
    } else if constexpr (n == 10) {
        const auto& [m0,m1,m2,m3,m4,m5,m6,m7,m8,m9] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1), rangeOf(&s, m2), rangeOf(&s, m3), rangeOf(&s, m4), rangeOf(&s, m5), rangeOf(&s, m6), rangeOf(&s, m7), rangeOf(&s, m8), rangeOf(&s, m9)};
    } else if constexpr (n == 11) {
        const auto& [m0,m1,m2,m3,m4,m5,m6,m7,m8,m9,m10] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1), rangeOf(&s, m2), rangeOf(&s, m3), rangeOf(&s, m4), rangeOf(&s, m5), rangeOf(&s, m6), rangeOf(&s, m7), rangeOf(&s, m8), rangeOf(&s, m9), rangeOf(&s, m10)};
    } else if constexpr (n == 12) {
        const auto& [m0,m1,m2,m3,m4,m5,m6,m7,m8,m9,m10,m11] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1), rangeOf(&s, m2), rangeOf(&s, m3), rangeOf(&s, m4), rangeOf(&s, m5), rangeOf(&s, m6), rangeOf(&s, m7), rangeOf(&s, m8), rangeOf(&s, m9), rangeOf(&s, m10), rangeOf(&s, m11)};
    } else if constexpr (n == 13) {
        const auto& [m0,m1,m2,m3,m4,m5,m6,m7,m8,m9,m10,m11,m12] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1), rangeOf(&s, m2), rangeOf(&s, m3), rangeOf(&s, m4), rangeOf(&s, m5), rangeOf(&s, m6), rangeOf(&s, m7), rangeOf(&s, m8), rangeOf(&s, m9), rangeOf(&s, m10), rangeOf(&s, m11), rangeOf(&s, m12)};
    } else if constexpr (n == 14) {
        const auto& [m0,m1,m2,m3,m4,m5,m6,m7,m8,m9,m10,m11,m12,m13] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1), rangeOf(&s, m2), rangeOf(&s, m3), rangeOf(&s, m4), rangeOf(&s, m5), rangeOf(&s, m6), rangeOf(&s, m7), rangeOf(&s, m8), rangeOf(&s, m9), rangeOf(&s, m10), rangeOf(&s, m11), rangeOf(&s, m12), rangeOf(&s, m13)};
    } else if constexpr (n == 15) {
        const auto& [m0,m1,m2,m3,m4,m5,m6,m7,m8,m9,m10,m11,m12,m13,m14] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1), rangeOf(&s, m2), rangeOf(&s, m3), rangeOf(&s, m4), rangeOf(&s, m5), rangeOf(&s, m6), rangeOf(&s, m7), rangeOf(&s, m8), rangeOf(&s, m9), rangeOf(&s, m10), rangeOf(&s, m11), rangeOf(&s, m12), rangeOf(&s, m13), rangeOf(&s, m14)};
    } else if constexpr (n == 16) {
        const auto& [m0,m1,m2,m3,m4,m5,m6,m7,m8,m9,m10,m11,m12,m13,m14,m15] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1), rangeOf(&s, m2), rangeOf(&s, m3), rangeOf(&s, m4), rangeOf(&s, m5), rangeOf(&s, m6), rangeOf(&s, m7), rangeOf(&s, m8), rangeOf(&s, m9), rangeOf(&s, m10), rangeOf(&s, m11), rangeOf(&s, m12), rangeOf(&s, m13), rangeOf(&s, m14), rangeOf(&s, m15)};
    } else if constexpr (n == 17) {
        const auto& [m0,m1,m2,m3,m4,m5,m6,m7,m8,m9,m10,m11,m12,m13,m14,m15,m16] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1), rangeOf(&s, m2), rangeOf(&s, m3), rangeOf(&s, m4), rangeOf(&s, m5), rangeOf(&s, m6), rangeOf(&s, m7), rangeOf(&s, m8), rangeOf(&s, m9), rangeOf(&s, m10), rangeOf(&s, m11), rangeOf(&s, m12), rangeOf(&s, m13), rangeOf(&s, m14), rangeOf(&s, m15), rangeOf(&s, m16)};
    } else if constexpr (n == 18) {
        const auto& [m0,m1,m2,m3,m4,m5,m6,m7,m8,m9,m10,m11,m12,m13,m14,m15,m16,m17] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1), rangeOf(&s, m2), rangeOf(&s, m3), rangeOf(&s, m4), rangeOf(&s, m5), rangeOf(&s, m6), rangeOf(&s, m7), rangeOf(&s, m8), rangeOf(&s, m9), rangeOf(&s, m10), rangeOf(&s, m11), rangeOf(&s, m12), rangeOf(&s, m13), rangeOf(&s, m14), rangeOf(&s, m15), rangeOf(&s, m16), rangeOf(&s, m17)};
    } else if constexpr (n == 19) {
        const auto& [m0,m1,m2,m3,m4,m5,m6,m7,m8,m9,m10,m11,m12,m13,m14,m15,m16,m17,m18] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1), rangeOf(&s, m2), rangeOf(&s, m3), rangeOf(&s, m4), rangeOf(&s, m5), rangeOf(&s, m6), rangeOf(&s, m7), rangeOf(&s, m8), rangeOf(&s, m9), rangeOf(&s, m10), rangeOf(&s, m11), rangeOf(&s, m12), rangeOf(&s, m13), rangeOf(&s, m14), rangeOf(&s, m15), rangeOf(&s, m16), rangeOf(&s, m17), rangeOf(&s, m18)};
    } else if constexpr (n == 20) {
        const auto& [m0,m1,m2,m3,m4,m5,m6,m7,m8,m9,m10,m11,m12,m13,m14,m15,m16,m17,m18,m19] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1), rangeOf(&s, m2), rangeOf(&s, m3), rangeOf(&s, m4), rangeOf(&s, m5), rangeOf(&s, m6), rangeOf(&s, m7), rangeOf(&s, m8), rangeOf(&s, m9), rangeOf(&s, m10), rangeOf(&s, m11), rangeOf(&s, m12), rangeOf(&s, m13), rangeOf(&s, m14), rangeOf(&s, m15), rangeOf(&s, m16), rangeOf(&s, m17), rangeOf(&s, m18), rangeOf(&s, m19)};
    } else if constexpr (n == 21) {
        const auto& [m0,m1,m2,m3,m4,m5,m6,m7,m8,m9,m10,m11,m12,m13,m14,m15,m16,m17,m18,m19,m20] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1), rangeOf(&s, m2), rangeOf(&s, m3), rangeOf(&s, m4), rangeOf(&s, m5), rangeOf(&s, m6), rangeOf(&s, m7), rangeOf(&s, m8), rangeOf(&s, m9), rangeOf(&s, m10), rangeOf(&s, m11), rangeOf(&s, m12), rangeOf(&s, m13), rangeOf(&s, m14), rangeOf(&s, m15), rangeOf(&s, m16), rangeOf(&s, m17), rangeOf(&s, m18), rangeOf(&s, m19), rangeOf(&s, m20)};
    } else if constexpr (n == 22) {
        const auto& [m0,m1,m2,m3,m4,m5,m6,m7,m8,m9,m10,m11,m12,m13,m14,m15,m16,m17,m18,m19,m20,m21] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1), rangeOf(&s, m2), rangeOf(&s, m3), rangeOf(&s, m4), rangeOf(&s, m5), rangeOf(&s, m6), rangeOf(&s, m7), rangeOf(&s, m8), rangeOf(&s, m9), rangeOf(&s, m10), rangeOf(&s, m11), rangeOf(&s, m12), rangeOf(&s, m13), rangeOf(&s, m14), rangeOf(&s, m15), rangeOf(&s, m16), rangeOf(&s, m17), rangeOf(&s, m18), rangeOf(&s, m19), rangeOf(&s, m20), rangeOf(&s, m21)};
    } else if constexpr (n == 23) {
        const auto& [m0,m1,m2,m3,m4,m5,m6,m7,m8,m9,m10,m11,m12,m13,m14,m15,m16,m17,m18,m19,m20,m21,m22] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1), rangeOf(&s, m2), rangeOf(&s, m3), rangeOf(&s, m4), rangeOf(&s, m5), rangeOf(&s, m6), rangeOf(&s, m7), rangeOf(&s, m8), rangeOf(&s, m9), rangeOf(&s, m10), rangeOf(&s, m11), rangeOf(&s, m12), rangeOf(&s, m13), rangeOf(&s, m14), rangeOf(&s, m15), rangeOf(&s, m16), rangeOf(&s, m17), rangeOf(&s, m18), rangeOf(&s, m19), rangeOf(&s, m20), rangeOf(&s, m21), rangeOf(&s, m22)};
    } else if constexpr (n == 24) {
        const auto& [m0,m1,m2,m3,m4,m5,m6,m7,m8,m9,m10,m11,m12,m13,m14,m15,m16,m17,m18,m19,m20,m21,m22,m23] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1), rangeOf(&s, m2), rangeOf(&s, m3), rangeOf(&s, m4), rangeOf(&s, m5), rangeOf(&s, m6), rangeOf(&s, m7), rangeOf(&s, m8), rangeOf(&s, m9), rangeOf(&s, m10), rangeOf(&s, m11), rangeOf(&s, m12), rangeOf(&s, m13), rangeOf(&s, m14), rangeOf(&s, m15), rangeOf(&s, m16), rangeOf(&s, m17), rangeOf(&s, m18), rangeOf(&s, m19), rangeOf(&s, m20), rangeOf(&s, m21), rangeOf(&s, m22), rangeOf(&s, m23)};
    } else if constexpr (n == 25) {
        const auto& [m0,m1,m2,m3,m4,m5,m6,m7,m8,m9,m10,m11,m12,m13,m14,m15,m16,m17,m18,m19,m20,m21,m22,m23,m24] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1), rangeOf(&s, m2), rangeOf(&s, m3), rangeOf(&s, m4), rangeOf(&s, m5), rangeOf(&s, m6), rangeOf(&s, m7), rangeOf(&s, m8), rangeOf(&s, m9), rangeOf(&s, m10), rangeOf(&s, m11), rangeOf(&s, m12), rangeOf(&s, m13), rangeOf(&s, m14), rangeOf(&s, m15), rangeOf(&s, m16), rangeOf(&s, m17), rangeOf(&s, m18), rangeOf(&s, m19), rangeOf(&s, m20), rangeOf(&s, m21), rangeOf(&s, m22), rangeOf(&s, m23), rangeOf(&s, m24)};
    } else if constexpr (n == 26) {
        const auto& [m0,m1,m2,m3,m4,m5,m6,m7,m8,m9,m10,m11,m12,m13,m14,m15,m16,m17,m18,m19,m20,m21,m22,m23,m24,m25] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1), rangeOf(&s, m2), rangeOf(&s, m3), rangeOf(&s, m4), rangeOf(&s, m5), rangeOf(&s, m6), rangeOf(&s, m7), rangeOf(&s, m8), rangeOf(&s, m9), rangeOf(&s, m10), rangeOf(&s, m11), rangeOf(&s, m12), rangeOf(&s, m13), rangeOf(&s, m14), rangeOf(&s, m15), rangeOf(&s, m16), rangeOf(&s, m17), rangeOf(&s, m18), rangeOf(&s, m19), rangeOf(&s, m20), rangeOf(&s, m21), rangeOf(&s, m22), rangeOf(&s, m23), rangeOf(&s, m24), rangeOf(&s, m25)};
    } else if constexpr (n == 27) {
        const auto& [m0,m1,m2,m3,m4,m5,m6,m7,m8,m9,m10,m11,m12,m13,m14,m15,m16,m17,m18,m19,m20,m21,m22,m23,m24,m25,m26] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1), rangeOf(&s, m2), rangeOf(&s, m3), rangeOf(&s, m4), rangeOf(&s, m5), rangeOf(&s, m6), rangeOf(&s, m7), rangeOf(&s, m8), rangeOf(&s, m9), rangeOf(&s, m10), rangeOf(&s, m11), rangeOf(&s, m12), rangeOf(&s, m13), rangeOf(&s, m14), rangeOf(&s, m15), rangeOf(&s, m16), rangeOf(&s, m17), rangeOf(&s, m18), rangeOf(&s, m19), rangeOf(&s, m20), rangeOf(&s, m21), rangeOf(&s, m22), rangeOf(&s, m23), rangeOf(&s, m24), rangeOf(&s, m25), rangeOf(&s, m26)};
    } else if constexpr (n == 28) {
        const auto& [m0,m1,m2,m3,m4,m5,m6,m7,m8,m9,m10,m11,m12,m13,m14,m15,m16,m17,m18,m19,m20,m21,m22,m23,m24,m25,m26,m27] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1), rangeOf(&s, m2), rangeOf(&s, m3), rangeOf(&s, m4), rangeOf(&s, m5), rangeOf(&s, m6), rangeOf(&s, m7), rangeOf(&s, m8), rangeOf(&s, m9), rangeOf(&s, m10), rangeOf(&s, m11), rangeOf(&s, m12), rangeOf(&s, m13), rangeOf(&s, m14), rangeOf(&s, m15), rangeOf(&s, m16), rangeOf(&s, m17), rangeOf(&s, m18), rangeOf(&s, m19), rangeOf(&s, m20), rangeOf(&s, m21), rangeOf(&s, m22), rangeOf(&s, m23), rangeOf(&s, m24), rangeOf(&s, m25), rangeOf(&s, m26), rangeOf(&s, m27)};
    } else if constexpr (n == 29) {
        const auto& [m0,m1,m2,m3,m4,m5,m6,m7,m8,m9,m10,m11,m12,m13,m14,m15,m16,m17,m18,m19,m20,m21,m22,m23,m24,m25,m26,m27,m28] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1), rangeOf(&s, m2), rangeOf(&s, m3), rangeOf(&s, m4), rangeOf(&s, m5), rangeOf(&s, m6), rangeOf(&s, m7), rangeOf(&s, m8), rangeOf(&s, m9), rangeOf(&s, m10), rangeOf(&s, m11), rangeOf(&s, m12), rangeOf(&s, m13), rangeOf(&s, m14), rangeOf(&s, m15), rangeOf(&s, m16), rangeOf(&s, m17), rangeOf(&s, m18), rangeOf(&s, m19), rangeOf(&s, m20), rangeOf(&s, m21), rangeOf(&s, m22), rangeOf(&s, m23), rangeOf(&s, m24), rangeOf(&s, m25), rangeOf(&s, m26), rangeOf(&s, m27), rangeOf(&s, m28)};
    } else if constexpr (n == 30) {
        const auto& [m0,m1,m2,m3,m4,m5,m6,m7,m8,m9,m10,m11,m12,m13,m14,m15,m16,m17,m18,m19,m20,m21,m22,m23,m24,m25,m26,m27,m28,m29] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1), rangeOf(&s, m2), rangeOf(&s, m3), rangeOf(&s, m4), rangeOf(&s, m5), rangeOf(&s, m6), rangeOf(&s, m7), rangeOf(&s, m8), rangeOf(&s, m9), rangeOf(&s, m10), rangeOf(&s, m11), rangeOf(&s, m12), rangeOf(&s, m13), rangeOf(&s, m14), rangeOf(&s, m15), rangeOf(&s, m16), rangeOf(&s, m17), rangeOf(&s, m18), rangeOf(&s, m19), rangeOf(&s, m20), rangeOf(&s, m21), rangeOf(&s, m22), rangeOf(&s, m23), rangeOf(&s, m24), rangeOf(&s, m25), rangeOf(&s, m26), rangeOf(&s, m27), rangeOf(&s, m28), rangeOf(&s, m29)};
    } else if constexpr (n == 31) {
        const auto& [m0,m1,m2,m3,m4,m5,m6,m7,m8,m9,m10,m11,m12,m13,m14,m15,m16,m17,m18,m19,m20,m21,m22,m23,m24,m25,m26,m27,m28,m29,m30] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1), rangeOf(&s, m2), rangeOf(&s, m3), rangeOf(&s, m4), rangeOf(&s, m5), rangeOf(&s, m6), rangeOf(&s, m7), rangeOf(&s, m8), rangeOf(&s, m9), rangeOf(&s, m10), rangeOf(&s, m11), rangeOf(&s, m12), rangeOf(&s, m13), rangeOf(&s, m14), rangeOf(&s, m15), rangeOf(&s, m16), rangeOf(&s, m17), rangeOf(&s, m18), rangeOf(&s, m19), rangeOf(&s, m20), rangeOf(&s, m21), rangeOf(&s, m22), rangeOf(&s, m23), rangeOf(&s, m24), rangeOf(&s, m25), rangeOf(&s, m26), rangeOf(&s, m27), rangeOf(&s, m28), rangeOf(&s, m29), rangeOf(&s, m30)};
    } else if constexpr (n == 32) {
        const auto& [m0,m1,m2,m3,m4,m5,m6,m7,m8,m9,m10,m11,m12,m13,m14,m15,m16,m17,m18,m19,m20,m21,m22,m23,m24,m25,m26,m27,m28,m29,m30,m31] = s;
        return {rangeOf(&s, m0), rangeOf(&s, m1), rangeOf(&s, m2), rangeOf(&s, m3), rangeOf(&s, m4), rangeOf(&s, m5), rangeOf(&s, m6), rangeOf(&s, m7), rangeOf(&s, m8), rangeOf(&s, m9), rangeOf(&s, m10), rangeOf(&s, m11), rangeOf(&s, m12), rangeOf(&s, m13), rangeOf(&s, m14), rangeOf(&s, m15), rangeOf(&s, m16), rangeOf(&s, m17), rangeOf(&s, m18), rangeOf(&s, m19), rangeOf(&s, m20), rangeOf(&s, m21), rangeOf(&s, m22), rangeOf(&s, m23), rangeOf(&s, m24), rangeOf(&s, m25), rangeOf(&s, m26), rangeOf(&s, m27), rangeOf(&s, m28), rangeOf(&s, m29), rangeOf(&s, m30), rangeOf(&s, m31)};
    }
}

}  // namespace penumbra::test
