/**
 * The wire between the Environment and its robots and viewers: the messages, and the
 * length-prefixed frame codec that carries them. No sockets live here.
 */
package robosim.protocol;
