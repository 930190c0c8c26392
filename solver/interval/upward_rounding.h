#pragma once
// The upward rounding mode for the lifetime of a scope: the kernels (files named
// *_kernel.cpp, compiled with -frounding-math) compute upper bounds with plain + - * /
// and lower bounds as -((-a) op b). Use it only in those files: elsewhere the compiler
// may fold or move floating point operations across the mode switch.

#include <cfenv>

namespace gesmi {

class UpwardRounding {
 public:
  UpwardRounding() : saved_(std::fegetround()) { std::fesetround(FE_UPWARD); }
  ~UpwardRounding() { std::fesetround(saved_); }
  UpwardRounding(const UpwardRounding&) = delete;
  UpwardRounding& operator=(const UpwardRounding&) = delete;

 private:
  int saved_;
};

}  // namespace gesmi
