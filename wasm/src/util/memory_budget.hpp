// Memory a computation will need, predicted from its size before it starts, so a design that would not
// fit gets a message in the designer's words instead of an out-of-memory failure minutes later.
//
// The models are upper bounds fitted to measured peaks (native peak RSS, bench/README.md "Memory"):
// the sparse Cholesky factor of a surface mesh under nested dissection grows like n log n, the rest
// (elements, Hessian, pattern file, optimizer state) like n. tests/native/test_memory_budget.cpp checks
// them against the CLI's measured peak.
#pragma once
#include <string>

namespace billow {

// Peak bytes to read a pattern of `triangles` triangles and inflate it (Newton with a sparse Cholesky).
double inflationBytes(long long triangles);

// Peak bytes to make the panels of a design at `patternTriangles` and optimize them against a target
// of `targetTriangles` (the inflation plus the adjoint solves, distance queries and the target).
double optimizationBytes(long long patternTriangles, long long targetTriangles);

// Bytes this process may still allocate: in WebAssembly the heap's maximum size minus what is in use;
// natively the machine's physical memory.
double availableBytes();

// Bytes the allocator has handed out and not yet had back (mallinfo's in-use count). In WebAssembly only; natively
// 0. Unlike the heap's size, it falls again when memory is freed, so a leak shows as a rise between two alike moments.
double bytesInUse();

// Where the budget comes from, in words ("a browser tab gives Billow 2.0 GB"), for messages.
std::string budgetDescription(double budgetBytes);

// Throws Error("memory.budget") when `needed` exceeds `budget`; `what` says what needs it ("Inflating
// this pattern (1,200,000 triangles)") and `remedy` what to do instead.
void requireMemory(double needed, double budget, const std::string& what, const std::string& remedy);

// "380 MB", "2.1 GB".
std::string formatBytes(double bytes);

}  // namespace billow
