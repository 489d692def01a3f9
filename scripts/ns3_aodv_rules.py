"""ns-3.37's AODV as SwarmNet's `aodv` plugin describes it: the parameters that make the plugin
behave as ns-3.37's aodv-routing-protocol.cc does where it departs from RFC 3561 (docs/plugins.md,
aodv; docs/history/validation-journal.md, "The saturated rows, and ns-3's control-message rules",
and each later rule's section there, listed in docs/validation.md, "ns-3.37's rules on SwarmNet's
side").

Two sequence-number rules (a broken route keeps its number; a RREQ leaves the route to its sender
without a valid number) and four control-message rules (a RREP forwarded over an invalid reverse
route; a RREP's IP TTL; RERRs only to precursors with a valid route, after a jitter; buffered
packets sent only on a RREP or at the discovery timer), and three route-update rules (a RREQ
overwrites the reverse route whatever its freshness; a message from a neighbour leaves its route
with number 0, unknown; a destination increments its number only when asked for exactly one
more), and ns-3's IP under its messages (a RREP, RERR or RREP-ACK takes the route to its
neighbour, and a node on the way relays it as IP; a message heard refreshes the route to its
sender before AODV reads it), and its RERRs (a broken link or a RERR reports routes in any
state, and a broken link the neighbour itself; a RREP puts a new entry, without precursors, in
the route's place), and its RREQ rate limit (every refused request waits on its own for the next
window), and what a RREP for this node does to its discovery (it ends only a search it finds under
way; the buffer leaves over the route as it stands), and when its routes age (every lookup ages
the whole table). The ns-3 engine refuses AODV without them;
the validation grid and the engine benchmark give them to SwarmNet's side so that both sides run
the same protocol.
"""

NS3_AODV_RULES = {
    "increment_seqno_on_break": False,
    "rreq_invalidates_sender_seqno": True,
    "rrep_over_invalid_reverse_route": True,
    "rrep_ip_ttl": True,
    "rerr_to_valid_precursors": True,
    "queue_released_by_rrep_only": True,
    "rreq_overwrites_reverse_route": True,
    "neighbor_route_forgets_seqno": True,
    "reply_seqno_plus_one_only": True,
    "control_via_route_to_neighbor": True,
    "ip_input_refreshes_routes": True,
    "rerr_covers_routes_in_any_state": True,
    "rrep_replaces_route": True,
    "rate_limited_requests_stack": True,
    "rrep_ends_search_only": True,
    "lookups_age_all_routes": True,
}


def set_arguments(prefix="network.routing.params"):
    """The rules as `swarmnet run` --set arguments."""
    return [arg for name, value in NS3_AODV_RULES.items()
            for arg in ("--set", f"{prefix}.{name}={str(value).lower()}")]
