/**
 * In-process links: robots that run in the Environment's JVM reach it through a registry of its
 * ports ({@link robosim.protocol.inprocess.InProcessPorts}), exchanging the wire's messages as
 * objects ({@link robosim.protocol.inprocess.MessageSink}) instead of frames over TCP.
 */
package robosim.protocol.inprocess;
