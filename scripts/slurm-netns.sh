# Sourced by scripts/slurm-local.sh: the nodes of a multi-node test cluster on
# one machine (start --nodes N). Each node cic-nK is a Linux network namespace
# /run/netns/cic-nK with its own address 10.77.0.(10+K) on a veth pair whose
# host end is on the bridge cicbr0 (10.77.0.1, where slurmctld listens), and
# its slurmd runs there with its own hostname (a UTS namespace): to Slurm,
# to Open MPI and to cic the nodes are separate hosts, reached over TCP.
#
# Why namespaces and not Slurm's multiple-slurmd mode: Debian's slurm-wlm is
# built without --enable-multiple-slurmd, so two slurmd on one host would fight
# over the port 6818 and the node name. In its own network namespace every
# slurmd has the port to itself, with NodeAddr its namespace's address; the
# files the daemons share are told apart by %n in slurm.conf (spool, pid, log).
# The file system (and munged's socket) stays shared, as an NFS home would be.
#
# Traffic goes only to addresses inside 10.77.0.0/24, which this script creates.

NETNS_BRIDGE=cicbr0
NETNS_HOST_ADDR=10.77.0.1
NETNS_PREFIX=cic-n

netns_node_name() { echo "$NETNS_PREFIX$1"; }
netns_node_addr() { echo "10.77.0.$((10 + $1))"; }

# Bridge, namespaces, veth pairs and addresses for nodes 1..N; idempotent.
netns_up() {
  local n=$1 k ns veth
  command -v ip >/dev/null || die "ip (iproute2) is missing: apt-get install iproute2"
  command -v nsenter >/dev/null || die "nsenter (util-linux) is missing"
  if ! ip link show "$NETNS_BRIDGE" >/dev/null 2>&1; then
    ip link add "$NETNS_BRIDGE" type bridge || die "cannot create the bridge $NETNS_BRIDGE (needs CAP_NET_ADMIN)"
  fi
  ip addr replace "$NETNS_HOST_ADDR/24" dev "$NETNS_BRIDGE"
  ip link set "$NETNS_BRIDGE" up
  for ((k = 1; k <= n; k++)); do
    ns=$(netns_node_name "$k")
    veth=cicv$k
    [ -e "/run/netns/$ns" ] || ip netns add "$ns" || die "cannot create the network namespace $ns"
    if ! ip link show "$veth" >/dev/null 2>&1; then
      ip link add "$veth" type veth peer name eth0 netns "$ns" || die "cannot create the veth pair $veth"
    fi
    ip link set "$veth" master "$NETNS_BRIDGE"
    ip link set "$veth" up
    ip -n "$ns" addr replace "$(netns_node_addr "$k")/24" dev eth0
    ip -n "$ns" link set eth0 up
    ip -n "$ns" link set lo up
    ip -n "$ns" route replace default via "$NETNS_HOST_ADDR"
  done
}

# Every namespace node (any count), its veth pair, and the bridge.
netns_down() {
  local ns k
  for ns in $(ip netns list 2>/dev/null | awk '{print $1}' | grep "^$NETNS_PREFIX[0-9]*$" || true); do
    k=${ns#"$NETNS_PREFIX"}
    netns_kill_all "$ns"
    ip link del "cicv$k" 2>/dev/null || true
    ip netns del "$ns" 2>/dev/null || true
  done
  ip link del "$NETNS_BRIDGE" 2>/dev/null || true
}

# Runs COMMAND... on node NS: in its network namespace, with its hostname.
# With CIC_NODE_PRIVATE=DIR the node does not see DIR (an empty tmpfs over it,
# in a mount namespace of its own), as a folder that is not on a shared file
# system: how the tests show that cic names what every host must see.
netns_exec() {
  local ns=$1
  shift
  [ -e "/run/netns/$ns" ] || die "no node $ns (start --nodes N first)"
  if [ -n "${CIC_NODE_PRIVATE:-}" ]; then
    # shellcheck disable=SC2016
    nsenter --net="/run/netns/$ns" unshare --uts --mount --propagation private \
      sh -c 'hostname "$0" && mount -t tmpfs cic-private "$CIC_NODE_PRIVATE" && exec "$@"' "$ns" "$@"
  else
    # shellcheck disable=SC2016
    nsenter --net="/run/netns/$ns" unshare --uts sh -c 'hostname "$0"; exec "$@"' "$ns" "$@"
  fi
}

# SIGKILL to every process of node NS (its slurmd, slurmstepd and jobs): the
# node is lost, as when a machine dies.
netns_kill_all() {
  local ns=$1 pids
  [ -e "/run/netns/$ns" ] || return 0
  pids=$(ip netns pids "$ns" 2>/dev/null | tr '\n' ' ')
  [ -z "${pids// /}" ] || kill -KILL $pids 2>/dev/null || true
}
