// CHOLMOD's OpenMP regions run on the thread that reaches them (internal to fitting).
#pragma once

namespace covmap::fitting::detail {

// Called before each solve. Keeps every OpenMP parallel region of the sparse factorization on the
// solving thread (serial_factorization.cpp says why and how) and reports whether this file's
// GOMP_parallel is the one the process resolves: false only where the OpenMP runtime's own was
// bound first (a fully static or deep-bound link), which the parallel levels then cover.
bool keep_sparse_factorization_serial();

}  // namespace covmap::fitting::detail
