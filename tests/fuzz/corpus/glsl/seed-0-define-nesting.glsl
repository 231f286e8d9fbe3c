0 macros that double at each level, 10 levels deep (1024 copies: bounded small)
#version 450
#define X0 1.0
#define X1 (X0 + X0)
#define X2 (X1 + X1)
#define X3 (X2 + X2)
#define X4 (X3 + X3)
#define X5 (X4 + X4)
#define X6 (X5 + X5)
#define X7 (X6 + X6)
#define X8 (X7 + X7)
#define X9 (X8 + X8)
#define X10 (X9 + X9)
#ifdef FEAT_A
#define F(x) (x * X10)
#else
#define F(x) (x)
#endif
layout(location = 0) out vec4 out_color;
void main() { out_color = vec4(F(0.001)); }
