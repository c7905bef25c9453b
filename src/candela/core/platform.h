#pragma once
// Platform macros shared by all of candela.

// Marks value code (math, sampling, materials, lights) that a CUDA build may later compile for the
// device. Empty on the CPU.
#define CANDELA_HD
