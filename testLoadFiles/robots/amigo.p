; AmigoBot: RoboSim robot model, ARIA's .p form (see docs/PARAMETER-FILES.md)
ConfigVersion 2.0

Section General settings
Class Pioneer
Subclass amigo
RobotRadius 180        ; mm, the circle round the body
RobotDiagonal 120      ; mm
RobotWidth 279         ; mm
RobotLength 330        ; mm, bumper to bumper
RobotLengthFront 160   ; mm ahead of the turning centre
RobotLengthRear 170    ; mm behind it
MaxVelocity 1000       ; mm/s, the fastest the robot ever drives
MaxRVelocity 300       ; deg/s, the fastest it ever turns

Section Conversion factors
; firmware units to ARIA's: what a Pioneer protocol server speaks
AngleConvFactor 0.001534 ; rad per angle unit (2 pi / 4096)
DistConvFactor 0.5083  ; mm per distance unit
VelConvFactor 0.6154   ; mm/s per speed unit
RangeConvFactor 1.0    ; mm per sonar range unit
DiffConvFactor 0.011   ; rad/s per mm/s of wheel speed difference
Vel2Divisor 20         ; VEL2 wheel speed divisor

Section Movement control parameters
; 0: the firmware's own value (RoboSim: 300 mm/s2 and 100 deg/s2)
TransAccel 0
TransDecel 0
RotAccel 0
RotDecel 0

Section Sonar parameters
SonarNum 8             ; transducers; six in front, two at the rear corners
; SonarUnit <number> <x mm forward> <y mm left> <heading deg>
SonarUnit 0 76 100 90
SonarUnit 1 125 75 41
SonarUnit 2 150 30 15
SonarUnit 3 150 -30 -15
SonarUnit 4 125 -75 -41
SonarUnit 5 76 -100 -90
SonarUnit 6 -140 -58 -145
SonarUnit 7 -140 58 145
