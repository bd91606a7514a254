// SPDX-License-Identifier: BSD-3-Clause
// The methods that live in a file of their own under transforms/methods/,
// one line each: BANDLIGHT_METHOD(KEY, MAKE) gives the method's key (a
// ChangeMethod value) and the function of its file that makes its registry
// entry (MethodEntry MAKE(ChangeMethod key), given its key). Read twice, with BANDLIGHT_METHOD defined:
// by transforms/Methods.h for the keys, by transforms/Methods.cpp for the
// registry, in this order (after the built-in methods, before the spectral
// reference). No include guard: it is a list, not a header.
#ifdef BANDLIGHT_METHOD
BANDLIGHT_METHOD(HUE_PLANE, HuePlaneMethod)
BANDLIGHT_METHOD(ROOTPOLY_PLATE, RootPolyPlateMethod)
#endif
