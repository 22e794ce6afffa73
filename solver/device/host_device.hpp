#pragma once
// Marks the functions that compile for the host and, under nvcc, for NVIDIA GPUs as well:
// the per-node and per-element arithmetic that the CPU solver and the device path
// (device_stepper.hpp) share, so that there is one source of it and CI tests it on the CPU.
#if defined(__CUDACC__)
#define RBCAL_HD __host__ __device__
#else
#define RBCAL_HD
#endif
