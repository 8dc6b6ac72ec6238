/**
 * Experiments: a sweep of runs from one YAML file, on this machine or on a SLURM cluster, and its
 * results.
 *
 * <p>{@link robosim.experiment.ExperimentReader} reads the file into an
 * {@link robosim.experiment.Experiment}, checking every run's values ({@link robosim.experiment.RunSpec})
 * before any runs. {@link robosim.experiment.RunExecutor} runs one run in its JVM and gives its
 * {@link robosim.experiment.RunRecord}, which {@link robosim.experiment.RunRecords} writes whole into
 * the results folder. {@link robosim.experiment.LocalRunner} runs a sweep's runs in worker JVMs,
 * several at once; {@link robosim.experiment.Slurm} writes and submits a cluster's job array instead.
 * {@link robosim.experiment.Collector} then builds {@code results.csv}, {@code summary.csv}
 * ({@link robosim.experiment.Summary}), the plots ({@link robosim.experiment.Plots}) and
 * {@code report.md}. The format and the outputs: docs/EXPERIMENTS.md.
 */
package robosim.experiment;
