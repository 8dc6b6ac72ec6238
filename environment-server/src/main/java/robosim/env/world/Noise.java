package robosim.env.world;

/**
 * The noise of a world's sensors and odometry, drawn from the run's seed so that runs repeat.
 *
 * @param sonarSigma    standard deviation of the Gaussian noise added to every sonar range, mm
 * @param laserSigma    standard deviation of the Gaussian noise added to every laser range, mm
 * @param odometryError odometry drift: standard deviation of the error per unit travelled, of the
 *                      distance per mm and of the heading per radian turned (MobileSim: 0.0075)
 */
public record Noise(double sonarSigma, double laserSigma, double odometryError) {
    /** No noise at all: the default. */
    public static final Noise NONE = new Noise(0, 0, 0);

    /** Checks that no figure is negative. */
    public Noise {
        if (sonarSigma < 0 || laserSigma < 0 || odometryError < 0) {
            throw new IllegalArgumentException("noise figures must not be negative: sonar " + sonarSigma
                    + ", laser " + laserSigma + ", odometry " + odometryError);
        }
    }

}
