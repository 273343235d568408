#pragma once
// Sparse linear systems A x = b: a square matrix assembled from (row, col, value) triplets
// and one solve() that runs a Krylov method (Belos) with a preconditioner (Ifpack2, MueLu),
// or a direct factorisation (Amesos2 KLU2), all from Trilinos. No Trilinos header is seen
// outside sparse_linear_solver.cpp.
//
// Each process solves its own system, on MPI_COMM_SELF. The first solve initialises MPI
// (unless the program has: no mpirun needed) and Kokkos (Serial: one thread); both are
// finalised at exit. solve() holds a lock, so calls from several threads run one at a time.
//
// Prescribed (Dirichlet) unknowns: the caller puts 1 on the diagonal, zeroes the rest of the
// row, sets b to the prescribed value and moves the known column entries to b (or leaves
// them, making the matrix nonsymmetric: then use GMRES or BiCGStab, not CG).
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace pilempm::core {

struct Triplet {
    int row = 0;
    int col = 0;
    double value = 0.0;
};

// A square n x n matrix in compressed rows, columns sorted within a row. Triplets at the same
// (row, col) are summed; an entry summed to zero stays in the pattern.
class SparseMatrix {
public:
    SparseMatrix() = default;
    // Throws std::invalid_argument for an index outside [0, n) or a value that is not finite.
    SparseMatrix(int n, const std::vector<Triplet>& triplets);

    int size() const { return n_; }
    std::size_t nonzeros() const { return values_.size(); }

    // The stored entry (0 when (row, col) is not in the pattern).
    double operator()(int row, int col) const;
    // Reuses the pattern: set_zero() keeps it, add() sums into an entry that must be in it
    // (std::out_of_range otherwise). A binary search in the row.
    void set_zero();
    void add(int row, int col, double value);

    // y = A x (x and y of size n).
    void multiply(const std::vector<double>& x, std::vector<double>& y) const;

    // Compressed rows: the entries of row i are [row_start[i], row_start[i + 1]).
    const std::vector<std::size_t>& row_start() const { return row_start_; }
    const std::vector<int>& columns() const { return columns_; }
    const std::vector<double>& values() const { return values_; }

private:
    std::size_t find(int row, int col) const;  // index into values_, or nonzeros()

    int n_ = 0;
    std::vector<std::size_t> row_start_ = {0};
    std::vector<int> columns_;
    std::vector<double> values_;
};

enum class KrylovMethod {
    gmres,     // any matrix (right-preconditioned, restarted)
    cg,        // symmetric positive definite A and preconditioner
    bicgstab,  // any matrix, short recurrences (less memory than GMRES)
    direct,    // sparse LU (Amesos2 KLU2); the preconditioner is not used
};

enum class Preconditioner {
    none,
    jacobi,     // point relaxation (Ifpack2): `relaxation_sweeps` damped Jacobi sweeps
    ilu,        // incomplete LU with level-of-fill `ilu_level` (Ifpack2 RILUK)
    ilut,       // threshold ILU (Ifpack2 ILUT): `ilut_fill`, `ilut_drop_tolerance`
    multigrid,  // smoothed-aggregation algebraic multigrid (MueLu), symmetric Gauss-Seidel
                // smoothing, KLU2 on the coarsest level; for elliptic (Poisson-like) rows
};

struct SolverOptions {
    KrylovMethod method = KrylovMethod::gmres;
    Preconditioner preconditioner = Preconditioner::ilu;
    double relative_tolerance = 1e-8;  // on ||b - A x|| / ||b||
    int max_iterations = 1000;
    int gmres_restart = 100;  // Krylov vectors kept before GMRES restarts
    int ilu_level = 0;        // ILU(k)
    double ilut_fill = 2.0;   // ILUT: entries kept per row, as a multiple of A's
    double ilut_drop_tolerance = 0.0;
    int relaxation_sweeps = 1;
    double relaxation_damping = 1.0;
    // MueLu: true (the default) builds the restriction as P^T; false for a nonsymmetric A.
    bool multigrid_symmetric = true;
};

struct SolveReport {
    bool converged = false;  // relative_residual <= relative_tolerance (and finite)
    int iterations = 0;      // Krylov iterations; direct: LU solves (1, +2 refinements at most)
    // ||b - A x|| / ||b|| (2-norms) of the returned x, computed here from the matrix, not the
    // solver's own estimate; 0 when b = 0 (then x = 0).
    double relative_residual = 0.0;
    std::string method;          // e.g. "GMRES(100)", "CG", "BiCGStab", "KLU2"
    std::string preconditioner;  // e.g. "ILU(0)", "Jacobi x1", "MueLu SA", "none"
    double setup_seconds = 0.0;  // the matrix copy and the preconditioner (or factorisation)
    double solve_seconds = 0.0;  // the iterations (or the triangular solves)
    bool setup_kept = false;     // a LinearSolver's symbolic set-up from its last solve
};

// Solves A x = b with x, on input, as the initial guess (resized to n with zeros when empty;
// direct ignores it). Not converging is no error: the report says so and x holds the last
// iterate. The first call costs about 0.3 s more (MPI and Kokkos start). Throws
// std::invalid_argument for sizes that do not match or a b or x that is not finite, and
// std::runtime_error, naming the method and the stage, for anything Trilinos throws (e.g. a
// zero pivot in the factorisation of a singular matrix).
SolveReport solve(const SparseMatrix& a, const std::vector<double>& b, std::vector<double>& x,
                  const SolverOptions& options = {});

// Systems solved one after another, as solve() solves each, keeping the preconditioner's
// (or the factorisation's) symbolic set-up while the matrix's pattern and the options stay
// the same: then only the new values are copied in and factorised (Ifpack2's compute()
// without initialize(): ILU's fill graph, the LU's ordering). Each answer is solve()'s to the
// bit, so a run resumed between two solves ends as it would have. The implicit steps of a
// consolidation pause share their pattern but when a point's stencil gains or loses a node.
// MueLu's hierarchy is built afresh each time.
class LinearSolver {
public:
    LinearSolver();
    ~LinearSolver();
    LinearSolver(LinearSolver&&) noexcept;
    LinearSolver& operator=(LinearSolver&&) noexcept;

    SolveReport solve(const SparseMatrix& a, const std::vector<double>& b, std::vector<double>& x,
                      const SolverOptions& options = {});
    // Solves that kept the last set-up (for tests and logs).
    int reused() const;

private:
    struct Kept;  // the Trilinos objects and the pattern they were built for
    std::unique_ptr<Kept> kept_;
};

// "GMRES", "CG", "BiCGStab", "direct"; "none", "Jacobi", "ILU", "ILUT", "multigrid".
std::string to_string(KrylovMethod method);
std::string to_string(Preconditioner preconditioner);

}  // namespace pilempm::core
