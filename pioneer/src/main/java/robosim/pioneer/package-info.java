/**
 * The Pioneer robot-server protocol, as ARIA, MobileSim and real Pioneer controllers speak it:
 * {@link robosim.pioneer.PioneerPacket} and its checksum, {@link robosim.pioneer.PacketDecoder}
 * for a byte stream, the client commands ({@link robosim.pioneer.Commands}), the server's status
 * packet ({@link robosim.pioneer.Sip}), configuration reply ({@link robosim.pioneer.ConfigPacket}),
 * simulated laser packets ({@link robosim.pioneer.LaserPacket}) and simulator status
 * ({@link robosim.pioneer.SimStat}), and a client for the protocol
 * ({@link robosim.pioneer.PioneerClient}).
 *
 * <p>Written from the protocol's facts: a packet is {@code FA FB N ID data CK_hi CK_lo}, its
 * multi-byte fields little-endian, its checksum the big-endian 16-bit word sum of ID and data.
 * The codec classes hold no sockets; only {@link robosim.pioneer.PioneerClient} does I/O.
 */
package robosim.pioneer;
