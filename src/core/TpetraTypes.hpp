// The Tpetra types choc uses everywhere (Debian's Trilinos 13.2 defaults: GO = long long).
#pragma once
#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>
#include <Tpetra_CrsMatrix_decl.hpp>
#include <Tpetra_Map_decl.hpp>
#include <Tpetra_MultiVector_decl.hpp>
#include <Tpetra_Operator.hpp>
#include <Tpetra_Vector_decl.hpp>

namespace choc {

using Teuchos::RCP;
using Teuchos::rcp;
using Comm = Teuchos::Comm<int>;
using Map = Tpetra::Map<>;
using LO = Map::local_ordinal_type;
using GO = Map::global_ordinal_type;
using CrsMatrix = Tpetra::CrsMatrix<double, LO, GO>;
using Vector = Tpetra::Vector<double, LO, GO>;
using MultiVector = Tpetra::MultiVector<double, LO, GO>;
using Operator = Tpetra::Operator<double, LO, GO>;

}  // namespace choc
