#pragma once
/// @file
/// Restbus: the rig stands in for a DBC node that is not on the bench (a gateway, an engine
/// ECU) and sends every cyclic message the DBC assigns to it. Load time only; the expansion
/// yields ordinary TX bindings, so the one TxScheduler sends them (docs/restbus.md).
///
///     [[restbus]]
///     node = "GW"                        # a BU_ node: every `BO_ ... GW` message is sent
///     set = { GW_IgnitionState = 2,      # optional: a number = a physical constant,
///             GW_VehicleSpeed = "vehicle_speed_mps" }  # a string = a model signal (as a
///                                        # [[tx.signal]] with convert = "none")
///     [[restbus.message]]                # optional, per message: its protection (counter,
///                                        #   checksum or e2e, as in a [[tx]])
///     name = "GW_Engine"
///     counter = { signal = "GW_EngineCounter", modulus = 16 }
///     checksum = { signal = "GW_EngineCrc", type = "crc8_sae_j1850" }
///
/// Each message goes out at its GenMsgCycleTime (BA_, else the BA_DEF_DEF_ default), each
/// signal not in `set` at its GenSigStartValue (raw; BA_DEF_DEF_ default; else 0). A message
/// without a cycle time (or 0) is not sent: one warning per node names them all. A message
/// also in [[tx]] is left to the [[tx]]. Errors (file:line): an unknown node (the DBC's nodes
/// listed), a node twice, a node that sends nothing, a message also in [[rx]], a `set` signal in
/// none of the messages sent, an unknown model signal, a `set` of a protected signal, a
/// [[restbus.message]] that is not one the restbus sends or is given twice.

#include "io/can/dbc/dbc_database.h"
#include "io/can/mapping/can_mapping.h"
#include "io/config/strict_table.h"

namespace rig::io::can::mapping {

/// Reads the `restbus` tables of `table` (if any) and appends their messages to mapping.tx;
/// mapping.rx and the [[tx]] entries must be read already. Skipped messages go to
/// mapping.warnings.
void expand_restbus(config::StrictTable& table, const dbc::Database& database,
                    const signals::Catalogue& catalogue, CanMapping& mapping);

}  // namespace rig::io::can::mapping
