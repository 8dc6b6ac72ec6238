ConfigVersion 2.0
;SectionFlags for : 
Section General settings
;  Robot parameters for the Pioneer 3 DX (p3dx), ARIA's .p form
Class Pioneer                 ; general type of robot
Subclass p3dx                 ; specific type of robot
RobotRadius           250      ; radius in mm
RobotDiagonal         120      ; half-height to diagonal of octagon
RobotWidth            425      ; width in mm
RobotLength           511      ; length in mm of the whole robot
RobotLengthFront      210      ; length in mm to the front of the robot
RobotLengthRear       301      ; length in mm to the rear of the robot
MaxVelocity           2200     ; absolute maximum velocity, mm/s
MaxRVelocity          500      ; absolute maximum rotational velocity, deg/s
TransAccel            300      ; translational acceleration, mm/s/s
TransDecel            300      ; translational deceleration, mm/s/s
RotAccel              100      ; rotational acceleration, deg/s/s
RotDecel              100      ; rotational deceleration, deg/s/s
DiffConvFactor        0.0056   ; wheel speed difference to rad/s
FrontBumpers          true     ; a front bump ring (RoboSim's bodies have one)
NumFrontBumpers       5        ; number of front bumpers
RearBumpers           true     ; a rear bump ring (RoboSim's bodies have one)
NumRearBumpers        5        ; number of rear bumpers

Section Conversion factors
; firmware units to ARIA's: what a Pioneer protocol server speaks
AngleConvFactor       0.001534 ; rad per angle unit (2 pi / 4096)
DistConvFactor        0.485    ; mm per distance unit
VelConvFactor         1.0      ; mm/s per speed unit
RangeConvFactor       1.0      ; mm per sonar range unit
Vel2Divisor           20       ; VEL2 wheel speed divisor

Section Sonar parameters
SonarNum 16                   ; number of sonar
SonarCycle 40                 ; ms between firings, one transducer of each bank of 8 (RoboSim key)
;SonarUnit <Number> <x position, mm> <y position, mm> <heading of disc, degrees>
SonarUnit 0 69 136 90
SonarUnit 1 114 119 50
SonarUnit 2 148 78 30
SonarUnit 3 166 27 10
SonarUnit 4 166 -27 -10
SonarUnit 5 148 -78 -30
SonarUnit 6 114 -119 -50
SonarUnit 7 69 -136 -90
SonarUnit 8 -157 -136 -90
SonarUnit 9 -203 -119 -130
SonarUnit 10 -237 -78 -150
SonarUnit 11 -255 -27 -170
SonarUnit 12 -255 27 170
SonarUnit 13 -237 78 150
SonarUnit 14 -203 119 130
SonarUnit 15 -157 136 90

Section Laser parameters
LaserX 18                     ; x location of laser, mm
LaserY 0                      ; y location of laser, mm
LaserTh 0                     ; rotation of laser, deg
LaserMaxRange 8000            ; max range of laser, mm (0: the default, 8000)
