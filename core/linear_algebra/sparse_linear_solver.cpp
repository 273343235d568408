// The one file that sees Trilinos (Tpetra, Belos, Ifpack2, MueLu; Amesos2 KLU2 through
// Ifpack2's Amesos2 wrapper). Debian's Trilinos 13.2 is instantiated for double, int local
// and long long global indices on Kokkos' Serial node only: the default template arguments.
#include "core/linear_algebra/sparse_linear_solver.hpp"

#include <BelosLinearProblem.hpp>
#include <BelosSolverFactory_Tpetra.hpp>
#include <BelosTpetraAdapter.hpp>
#include <Ifpack2_Factory.hpp>
#include <MueLu_CreateTpetraPreconditioner.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <mutex>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace pilempm::core {

namespace {

using Map = Tpetra::Map<>;
using LO = Map::local_ordinal_type;
using GO = Map::global_ordinal_type;
using Node = Map::node_type;
using CrsMatrix = Tpetra::CrsMatrix<double, LO, GO, Node>;
using RowMatrix = Tpetra::RowMatrix<double, LO, GO, Node>;
using MultiVector = Tpetra::MultiVector<double, LO, GO, Node>;
using Operator = Tpetra::Operator<double, LO, GO, Node>;
using Teuchos::RCP;
using Teuchos::rcp;

bool all_finite(const std::vector<double>& v) {
    return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

double norm2(const std::vector<double>& v) {
    return std::sqrt(std::inner_product(v.begin(), v.end(), v.begin(), 0.0));
}

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// MPI (when nobody has) and Kokkos once per process; finalised by atexit, which runs after
// the static objects constructed later (Tpetra's own caches) are destroyed. MPI is needed
// even for one process: Debian's Trilinos is the MPI build and MueLu's hierarchy summary
// casts the communicator to Teuchos::MpiComm (a Teuchos::SerialComm crashes there).
void initialise_trilinos() {
    static const bool initialised = [] {
        if (!Tpetra::isInitialized()) {
            int argc = 0;
            char** argv = nullptr;
            Tpetra::initialize(&argc, &argv, MPI_COMM_SELF);
            std::atexit([] { Tpetra::finalize(); });
        }
        return true;
    }();
    (void)initialised;
}

std::string method_name(const SolverOptions& o) {
    switch (o.method) {
        case KrylovMethod::gmres: return "GMRES(" + std::to_string(o.gmres_restart) + ")";
        case KrylovMethod::cg: return "CG";
        case KrylovMethod::bicgstab: return "BiCGStab";
        case KrylovMethod::direct: return "KLU2";
    }
    return "?";
}

std::string preconditioner_name(const SolverOptions& o) {
    if (o.method == KrylovMethod::direct) return "none";
    switch (o.preconditioner) {
        case Preconditioner::none: return "none";
        case Preconditioner::jacobi: return "Jacobi x" + std::to_string(o.relaxation_sweeps);
        case Preconditioner::ilu: return "ILU(" + std::to_string(o.ilu_level) + ")";
        case Preconditioner::ilut: {
            std::string fill = std::to_string(o.ilut_fill);
            fill.erase(fill.find_last_not_of('0') + 1);
            if (fill.back() == '.') fill.pop_back();
            return "ILUT(" + fill + ")";
        }
        case Preconditioner::multigrid: return "MueLu SA";
    }
    return "?";
}

// Teuchos' exception text on one line, without its blank lines and "Throw number = N".
std::string one_line(const std::string& text) {
    std::string out, line;
    std::istringstream in(text);
    while (std::getline(in, line)) {
        const bool blank = line.find_first_not_of(" \t") == std::string::npos;
        if (blank || line.rfind("Throw number", 0) == 0) continue;
        if (!out.empty()) out += out.back() == ':' ? " " : "; ";
        out += line;
    }
    return out;
}

// Runs one stage that calls Trilinos; anything it throws comes out as std::runtime_error
// naming the solve and the stage.
template <class F>
auto guarded(const std::string& what, const std::string& stage, F&& f) -> decltype(f()) {
    try {
        return f();
    } catch (const std::exception& e) {
        throw std::runtime_error("pilempm::core::solve (" + what + "): " + stage + " failed: " +
                                 one_line(e.what()));
    } catch (...) {
        throw std::runtime_error("pilempm::core::solve (" + what + "): " + stage +
                                 " failed with an unknown exception");
    }
}

RCP<CrsMatrix> to_tpetra(const SparseMatrix& a, const RCP<const Map>& map) {
    const std::size_t n = static_cast<std::size_t>(a.size());
    Teuchos::ArrayRCP<std::size_t> start(n + 1);
    Teuchos::ArrayRCP<LO> columns(a.nonzeros());
    Teuchos::ArrayRCP<double> values(a.nonzeros());
    std::copy(a.row_start().begin(), a.row_start().end(), start.begin());
    std::copy(a.columns().begin(), a.columns().end(), columns.begin());
    std::copy(a.values().begin(), a.values().end(), values.begin());
    auto m = rcp(new CrsMatrix(map, map, start, columns, values));
    m->fillComplete(map, map);
    return m;
}

void copy_in(const std::vector<double>& v, MultiVector& mv) {
    auto data = mv.getDataNonConst(0);
    std::copy(v.begin(), v.end(), data.begin());
}

void copy_out(const MultiVector& mv, std::vector<double>& v) {
    auto data = mv.getData(0);
    std::copy(data.begin(), data.end(), v.begin());
}

using IfpackPreconditioner = Ifpack2::Preconditioner<double, LO, GO, Node>;

// MueLu's smoothed-aggregation hierarchy on a, built afresh.
RCP<Operator> make_multigrid(const SolverOptions& o, const RCP<CrsMatrix>& a) {
    Teuchos::ParameterList p;
    p.set("verbosity", "none");
    p.set("multigrid algorithm", "sa");
    p.set("problem: symmetric", o.multigrid_symmetric);
    p.set("smoother: type", "RELAXATION");
    p.sublist("smoother: params").set("relaxation: type", "Symmetric Gauss-Seidel");
    p.sublist("smoother: params").set("relaxation: sweeps", 1);
    p.set("coarse: type", "KLU2");
    RCP<Operator> op = a;
    return MueLu::CreateTpetraPreconditioner(op, p);
}

// The Ifpack2 operator o asks for on a (relaxation, ILU, ILUT, or KLU2 for direct),
// initialised (its symbolic part: ILU's fill graph, the LU's ordering) but not computed;
// null for none and multigrid.
RCP<IfpackPreconditioner> make_ifpack2(const SolverOptions& o, const RCP<CrsMatrix>& a) {
    std::string type;
    Teuchos::ParameterList p;
    if (o.method == KrylovMethod::direct) {
        type = "AMESOS2";
        p.sublist("Amesos2");  // Ifpack2 wants a sublist "Amesos2", even an empty one
        p.set("Amesos2 solver name", "KLU2");
    } else {
        switch (o.preconditioner) {
            case Preconditioner::jacobi:
                type = "RELAXATION";
                p.set("relaxation: type", "Jacobi");
                p.set("relaxation: sweeps", o.relaxation_sweeps);
                p.set("relaxation: damping factor", o.relaxation_damping);
                break;
            case Preconditioner::ilu:
                type = "RILUK";
                p.set("fact: iluk level-of-fill", o.ilu_level);
                break;
            case Preconditioner::ilut:
                type = "ILUT";
                p.set("fact: ilut level-of-fill", o.ilut_fill);
                p.set("fact: drop tolerance", o.ilut_drop_tolerance);
                break;
            default: return Teuchos::null;
        }
    }
    auto prec = Ifpack2::Factory::create<RowMatrix>(type, a);
    prec->setParameters(p);
    prec->initialize();
    return prec;
}

// Options that change what make_ifpack2 builds (not the tolerances).
bool same_setup(const SolverOptions& a, const SolverOptions& b) {
    return a.method == b.method && a.preconditioner == b.preconditioner && a.ilu_level == b.ilu_level &&
           a.ilut_fill == b.ilut_fill && a.ilut_drop_tolerance == b.ilut_drop_tolerance &&
           a.relaxation_sweeps == b.relaxation_sweeps && a.relaxation_damping == b.relaxation_damping;
}

// a's values into a matrix of its pattern: its graph, and so what was initialised on it, stays.
void replace_values(const SparseMatrix& a, CrsMatrix& m, const RCP<const Map>& map) {
    m.resumeFill();
    const auto& start = a.row_start();
    for (int row = 0; row < a.size(); ++row) {
        const auto first = static_cast<Teuchos::ArrayView<const LO>::size_type>(start[row]);
        const auto count = static_cast<Teuchos::ArrayView<const LO>::size_type>(start[row + 1] - start[row]);
        if (count == 0) continue;
        const Teuchos::ArrayView<const LO> cols(a.columns().data() + first, count);
        const Teuchos::ArrayView<const double> vals(a.values().data() + first, count);
        if (m.replaceLocalValues(row, cols, vals) != count)
            throw std::runtime_error("row " + std::to_string(row) + " is not in the kept pattern");
    }
    m.fillComplete(map, map);
}

// x = LU \ b, then up to two steps of iterative refinement while the residual is above the
// tolerance. Returns the number of triangular solves.
int direct_solve(const SparseMatrix& a, const RCP<CrsMatrix>& ta, const RCP<IfpackPreconditioner>& lu,
                 const std::vector<double>& b, std::vector<double>& x, const SolverOptions& o,
                 const std::string& what, SolveReport& report) {
    const auto solve_start = std::chrono::steady_clock::now();
    MultiVector r(ta->getRangeMap(), 1), dx(ta->getDomainMap(), 1);
    std::vector<double> residual = b, ax(b.size()), correction(b.size());
    std::fill(x.begin(), x.end(), 0.0);
    const double b_norm = norm2(b);
    int solves = 0;
    for (; solves < 3; ++solves) {
        if (solves > 0 && norm2(residual) <= o.relative_tolerance * b_norm) break;
        copy_in(residual, r);
        guarded(what, "triangular solve", [&] { lu->apply(r, dx); });
        copy_out(dx, correction);
        for (std::size_t i = 0; i < x.size(); ++i) x[i] += correction[i];
        a.multiply(x, ax);
        for (std::size_t i = 0; i < x.size(); ++i) residual[i] = b[i] - ax[i];
    }
    report.solve_seconds = seconds_since(solve_start);
    return solves;
}

int krylov_solve(const RCP<CrsMatrix>& ta, const RCP<Operator>& prec, const std::vector<double>& b,
                 std::vector<double>& x, const SolverOptions& o, const std::string& what, SolveReport& report) {
    const auto solve_start = std::chrono::steady_clock::now();
    auto tb = rcp(new MultiVector(ta->getRangeMap(), 1));
    auto tx = rcp(new MultiVector(ta->getDomainMap(), 1));
    copy_in(b, *tb);
    copy_in(x, *tx);
    const int iterations = guarded(what, "Krylov solve", [&] {
        auto params = Teuchos::parameterList();
        params->set("Convergence Tolerance", o.relative_tolerance);
        params->set("Maximum Iterations", o.max_iterations);
        params->set("Verbosity", static_cast<int>(Belos::Errors));
        params->set("Output Stream", Teuchos::rcpFromRef(std::cerr));
        params->set("Implicit Residual Scaling", "Norm of RHS");
        std::string name;
        if (o.method == KrylovMethod::gmres) {
            name = "GMRES";
            params->set("Num Blocks", o.gmres_restart);
            params->set("Maximum Restarts", o.max_iterations / std::max(o.gmres_restart, 1) + 1);
            params->set("Explicit Residual Scaling", "Norm of RHS");
        } else if (o.method == KrylovMethod::cg) {
            name = "CG";
        } else {
            name = "BICGSTAB";
        }
        Belos::SolverFactory<double, MultiVector, Operator> factory;
        auto solver = factory.create(name, params);
        auto problem = rcp(new Belos::LinearProblem<double, MultiVector, Operator>(ta, tx, tb));
        // CG keeps A symmetric by preconditioning from the left (its residual is still
        // b - A x); the others precondition from the right, so theirs is the true residual.
        if (prec != Teuchos::null) {
            if (o.method == KrylovMethod::cg) problem->setLeftPrec(prec);
            else problem->setRightPrec(prec);
        }
        if (!problem->setProblem())
            throw std::runtime_error("Belos::LinearProblem::setProblem() refused the system");
        solver->setProblem(problem);
        solver->solve();
        return solver->getNumIters();
    });
    copy_out(*tx, x);
    report.solve_seconds = seconds_since(solve_start);
    return iterations;
}

}  // namespace

// --- SparseMatrix --------------------------------------------------------------------------

SparseMatrix::SparseMatrix(int n, const std::vector<Triplet>& triplets) : n_(n) {
    if (n < 0) throw std::invalid_argument("SparseMatrix: negative size " + std::to_string(n));
    for (const Triplet& t : triplets) {
        if (t.row < 0 || t.row >= n || t.col < 0 || t.col >= n)
            throw std::invalid_argument("SparseMatrix: entry (" + std::to_string(t.row) + ", " +
                                        std::to_string(t.col) + ") outside a matrix of size " +
                                        std::to_string(n));
        if (!std::isfinite(t.value))
            throw std::invalid_argument("SparseMatrix: entry (" + std::to_string(t.row) + ", " +
                                        std::to_string(t.col) + ") is not finite");
    }
    // The triplets bucketed by row (a counting sort: O(entries), where a sort of all the
    // entries took most of a consolidation step's assembly), then each row's duplicates
    // summed in the triplets' order through a marker per column, and its few distinct
    // columns sorted.
    const std::size_t rows = static_cast<std::size_t>(n);
    std::vector<std::size_t> bucket_start(rows + 1, 0);
    for (const Triplet& t : triplets) ++bucket_start[static_cast<std::size_t>(t.row) + 1];
    std::partial_sum(bucket_start.begin(), bucket_start.end(), bucket_start.begin());
    std::vector<std::size_t> by_row(triplets.size());
    {
        std::vector<std::size_t> next(bucket_start.begin(), bucket_start.end() - 1);
        for (std::size_t k = 0; k < triplets.size(); ++k) by_row[next[static_cast<std::size_t>(triplets[k].row)]++] = k;
    }
    row_start_.assign(rows + 1, 0);
    columns_.reserve(triplets.size() / 4);
    values_.reserve(triplets.size() / 4);
    std::vector<int> seen_in_row(rows, -1);
    std::vector<std::size_t> slot(rows, 0);
    std::vector<std::pair<int, double>> row_entries;
    for (std::size_t r = 0; r < rows; ++r) {
        row_entries.clear();
        for (std::size_t b = bucket_start[r]; b < bucket_start[r + 1]; ++b) {
            const Triplet& t = triplets[by_row[b]];
            const auto c = static_cast<std::size_t>(t.col);
            if (seen_in_row[c] != static_cast<int>(r)) {
                seen_in_row[c] = static_cast<int>(r);
                slot[c] = row_entries.size();
                row_entries.push_back({t.col, t.value});
            } else {
                row_entries[slot[c]].second += t.value;
            }
        }
        std::sort(row_entries.begin(), row_entries.end(),
                  [](const auto& a, const auto& b) { return a.first < b.first; });
        for (const auto& [col, value] : row_entries) {
            columns_.push_back(col);
            values_.push_back(value);
        }
        row_start_[r + 1] = columns_.size();
    }
}

std::size_t SparseMatrix::find(int row, int col) const {
    if (row < 0 || row >= n_) return nonzeros();
    const auto first = columns_.begin() + static_cast<std::ptrdiff_t>(row_start_[row]);
    const auto last = columns_.begin() + static_cast<std::ptrdiff_t>(row_start_[row + 1]);
    const auto it = std::lower_bound(first, last, col);
    return it != last && *it == col ? static_cast<std::size_t>(it - columns_.begin()) : nonzeros();
}

double SparseMatrix::operator()(int row, int col) const {
    const std::size_t k = find(row, col);
    return k < nonzeros() ? values_[k] : 0.0;
}

void SparseMatrix::set_zero() { std::fill(values_.begin(), values_.end(), 0.0); }

void SparseMatrix::add(int row, int col, double value) {
    const std::size_t k = find(row, col);
    if (k == nonzeros())
        throw std::out_of_range("SparseMatrix::add: (" + std::to_string(row) + ", " +
                                std::to_string(col) + ") is not in the pattern");
    if (!std::isfinite(value))
        throw std::invalid_argument("SparseMatrix::add: value at (" + std::to_string(row) + ", " +
                                    std::to_string(col) + ") is not finite");
    values_[k] += value;
}

void SparseMatrix::multiply(const std::vector<double>& x, std::vector<double>& y) const {
    if (x.size() != static_cast<std::size_t>(n_))
        throw std::invalid_argument("SparseMatrix::multiply: x has " + std::to_string(x.size()) +
                                    " entries for a matrix of size " + std::to_string(n_));
    y.resize(static_cast<std::size_t>(n_));
    for (int i = 0; i < n_; ++i) {
        double sum = 0.0;
        for (std::size_t k = row_start_[i]; k < row_start_[i + 1]; ++k)
            sum += values_[k] * x[static_cast<std::size_t>(columns_[k])];
        y[static_cast<std::size_t>(i)] = sum;
    }
}

// --- solve ---------------------------------------------------------------------------------

std::string to_string(KrylovMethod method) {
    switch (method) {
        case KrylovMethod::gmres: return "GMRES";
        case KrylovMethod::cg: return "CG";
        case KrylovMethod::bicgstab: return "BiCGStab";
        case KrylovMethod::direct: return "direct";
    }
    return "?";
}

std::string to_string(Preconditioner preconditioner) {
    switch (preconditioner) {
        case Preconditioner::none: return "none";
        case Preconditioner::jacobi: return "Jacobi";
        case Preconditioner::ilu: return "ILU";
        case Preconditioner::ilut: return "ILUT";
        case Preconditioner::multigrid: return "multigrid";
    }
    return "?";
}

// --- LinearSolver ----------------------------------------------------------------------------

struct LinearSolver::Kept {
    RCP<const Map> map;
    RCP<CrsMatrix> matrix;
    RCP<IfpackPreconditioner> prec;  // initialised on matrix's graph; null: none, multigrid
    std::vector<std::size_t> row_start;
    std::vector<int> columns;
    SolverOptions options;
    int reused = 0;
};

LinearSolver::LinearSolver() = default;
LinearSolver::~LinearSolver() = default;
LinearSolver::LinearSolver(LinearSolver&&) noexcept = default;
LinearSolver& LinearSolver::operator=(LinearSolver&&) noexcept = default;

int LinearSolver::reused() const { return kept_ ? kept_->reused : 0; }

SolveReport LinearSolver::solve(const SparseMatrix& a, const std::vector<double>& b, std::vector<double>& x,
                                const SolverOptions& options) {
    const std::size_t n = static_cast<std::size_t>(a.size());
    if (x.empty()) x.assign(n, 0.0);
    if (b.size() != n || x.size() != n)
        throw std::invalid_argument("pilempm::core::solve: b has " + std::to_string(b.size()) +
                                    " and x " + std::to_string(x.size()) +
                                    " entries for a matrix of size " + std::to_string(n));
    if (!all_finite(b) || !all_finite(x))
        throw std::invalid_argument("pilempm::core::solve: b or the initial x is not finite");
    if (!(options.relative_tolerance > 0.0) || options.max_iterations < 1 ||
        options.gmres_restart < 1)
        throw std::invalid_argument(
            "pilempm::core::solve: relative_tolerance, max_iterations and gmres_restart must be "
            "positive");

    SolveReport report;
    report.method = method_name(options);
    report.preconditioner = preconditioner_name(options);
    const std::string what = report.method + " + " + report.preconditioner;
    const double b_norm = norm2(b);
    if (b_norm == 0.0) {  // x = 0 exactly
        std::fill(x.begin(), x.end(), 0.0);
        report.converged = true;
        return report;
    }

    static std::mutex mutex;
    const std::lock_guard<std::mutex> lock(mutex);
    initialise_trilinos();
    const bool direct = options.method == KrylovMethod::direct;
    const bool multigrid = !direct && options.preconditioner == Preconditioner::multigrid;
    // Only the very same pattern: a larger kept one would give an ILU of other fill than a
    // fresh solve's, and a run resumed between two solves would not end as it would have.
    const bool keep = kept_ && kept_->matrix != Teuchos::null && same_setup(kept_->options, options) &&
                      kept_->row_start == a.row_start() && kept_->columns == a.columns();
    try {
        const auto start = std::chrono::steady_clock::now();
        if (!kept_) kept_ = std::make_unique<Kept>();
        Kept& k = *kept_;
        if (keep) {
            guarded(what, "matrix copy", [&] { replace_values(a, *k.matrix, k.map); });
            ++k.reused;
            report.setup_kept = !multigrid;  // MueLu's hierarchy is built afresh all the same
        } else {
            guarded(what, "matrix copy", [&] {
                k.map = rcp(new Map(static_cast<Tpetra::global_size_t>(n), GO{0},
                                    rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF))));
                k.matrix = to_tpetra(a, k.map);
            });
            k.row_start = a.row_start();
            k.columns = a.columns();
            k.options = options;
            k.prec = Teuchos::null;
        }
        const std::string setup = direct ? "factorisation" : "preconditioner setup";
        RCP<Operator> prec;
        guarded(what, setup, [&] {
            if (multigrid) {
                prec = make_multigrid(options, k.matrix);
                return;
            }
            if (!keep) k.prec = make_ifpack2(options, k.matrix);
            if (k.prec != Teuchos::null) k.prec->compute();  // the values, on the kept symbolic set-up
            prec = k.prec;
        });
        report.setup_seconds = seconds_since(start);
        report.iterations = direct ? direct_solve(a, k.matrix, k.prec, b, x, options, what, report)
                                   : krylov_solve(k.matrix, prec, b, x, options, what, report);
    } catch (...) {
        kept_.reset();  // half set up: the next solve starts afresh
        throw;
    }

    std::vector<double> ax;
    a.multiply(x, ax);
    double r2 = 0.0;
    for (std::size_t i = 0; i < n; ++i) r2 += (b[i] - ax[i]) * (b[i] - ax[i]);
    report.relative_residual = std::sqrt(r2) / b_norm;
    report.converged = std::isfinite(report.relative_residual) &&
                       report.relative_residual <= options.relative_tolerance;
    return report;
}

SolveReport solve(const SparseMatrix& a, const std::vector<double>& b, std::vector<double>& x,
                  const SolverOptions& options) {
    return LinearSolver().solve(a, b, x, options);
}

}  // namespace pilempm::core
