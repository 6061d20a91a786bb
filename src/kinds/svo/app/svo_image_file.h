#pragma once
// The SVO kind's image as a file (app/kind_image_file.h): the thesis' octree words have no header,
// so `validate` reads a file no other kind recognises as one (its own --root and --max-depth), and
// `golden`/`replay` take it as --svo.

#include "app/kind_image_file.h"
#include "kinds/svo/svo_kind.h"

namespace rtu {

template <>
struct KindImageFile<SvoKind> {
  static constexpr bool kByHeader = false;
};

}  // namespace rtu
