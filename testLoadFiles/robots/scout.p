ConfigVersion 2.0
Section General settings
;  The Nomadic Scout (a round robot, two wheels 345 mm apart, a ring of 16 sonars), ARIA's .p form
Class Scout                   ; general type of robot
Subclass scout                ; specific type of robot
RobotShape round              ; a disc of RobotRadius
RobotRadius           205      ; radius in mm: the Scout is round
RobotDiagonal         205      ; unused for a round body
RobotWidth            410      ; diameter, mm
RobotLength           410      ; diameter, mm
RobotLengthFront      205      ; mm
RobotLengthRear       205      ; mm
MaxVelocity           1000     ; absolute maximum velocity, mm/s
MaxRVelocity          120      ; absolute maximum rotational velocity, deg/s
TransAccel            500      ; mm/s/s
TransDecel            500      ; mm/s/s
RotAccel              180      ; deg/s/s
RotDecel              180      ; deg/s/s
DiffConvFactor        0.005794 ; ARIA's factor: the Scout's wheels are 345 mm apart
SonarMaxRange         6477     ; 255 inches, the Scout's longest sonar reading

Section Sonar parameters
SonarNum 16                   ; 16 sonars, 22.5 degrees apart, sonar 0 ahead, counter-clockwise
SonarUnit 0 190.0 0.0 0
SonarUnit 1 175.5 72.7 22.5
SonarUnit 2 134.4 134.4 45
SonarUnit 3 72.7 175.5 67.5
SonarUnit 4 0.0 190.0 90
SonarUnit 5 -72.7 175.5 112.5
SonarUnit 6 -134.4 134.4 135
SonarUnit 7 -175.5 72.7 157.5
SonarUnit 8 -190.0 0.0 180
SonarUnit 9 -175.5 -72.7 -157.5
SonarUnit 10 -134.4 -134.4 -135
SonarUnit 11 -72.7 -175.5 -112.5
SonarUnit 12 -0.0 -190.0 -90
SonarUnit 13 72.7 -175.5 -67.5
SonarUnit 14 134.4 -134.4 -45
SonarUnit 15 175.5 -72.7 -22.5
