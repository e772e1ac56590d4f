(define (problem strips-sat-x-1)
(:domain satellite)
(:objects
	satellite0 - satellite
	instrument0 - instrument
	instrument1 - instrument
	instrument2 - instrument
	instrument3 - instrument
	instrument4 - instrument
	satellite1 - satellite
	instrument5 - instrument
	satellite2 - satellite
	instrument6 - instrument
	instrument7 - instrument
	satellite3 - satellite
	instrument8 - instrument
	instrument9 - instrument
	instrument10 - instrument
	instrument11 - instrument
	satellite4 - satellite
	instrument12 - instrument
	instrument13 - instrument
	instrument14 - instrument
	image4 - mode
	spectrograph2 - mode
	image0 - mode
	spectrograph1 - mode
	infrared3 - mode
	GroundStation0 - direction
	Star1 - direction
	GroundStation9 - direction
	Star6 - direction
	Star4 - direction
	GroundStation5 - direction
	GroundStation2 - direction
	GroundStation3 - direction
	GroundStation7 - direction
	GroundStation8 - direction
	Star10 - direction
	Planet11 - direction
	Star12 - direction
	Planet13 - direction
	Phenomenon14 - direction
	Planet15 - direction
	Star16 - direction
	Phenomenon17 - direction
	Star18 - direction
	Phenomenon19 - direction
	Phenomenon20 - direction
	Phenomenon21 - direction
	Planet22 - direction
	Phenomenon23 - direction
	Planet24 - direction
	Planet25 - direction
	Planet26 - direction
	Star27 - direction
	Star28 - direction
	Star29 - direction
)
(:init
	(supports instrument0 image4)
	(supports instrument0 infrared3)
	(supports instrument0 spectrograph2)
	(calibration_target instrument0 GroundStation9)
	(calibration_target instrument0 Star4)
	(calibration_target instrument0 Star1)
	(supports instrument1 spectrograph1)
	(supports instrument1 image4)
	(supports instrument1 image0)
	(calibration_target instrument1 GroundStation9)
	(calibration_target instrument1 GroundStation7)
	(supports instrument2 image0)
	(calibration_target instrument2 Star6)
	(supports instrument3 spectrograph1)
	(calibration_target instrument3 GroundStation3)
	(calibration_target instrument3 Star6)
	(supports instrument4 image0)
	(supports instrument4 spectrograph2)
	(supports instrument4 image4)
	(calibration_target instrument4 GroundStation7)
	(calibration_target instrument4 GroundStation9)
	(on_board instrument0 satellite0)
	(on_board instrument1 satellite0)
	(on_board instrument2 satellite0)
	(on_board instrument3 satellite0)
	(on_board instrument4 satellite0)
	(power_avail satellite0)
	(pointing satellite0 GroundStation9)
	(supports instrument5 infrared3)
	(calibration_target instrument5 GroundStation8)
	(calibration_target instrument5 Star6)
	(on_board instrument5 satellite1)
	(power_avail satellite1)
	(pointing satellite1 Star18)
	(supports instrument6 image4)
	(calibration_target instrument6 Star1)
	(supports instrument7 spectrograph1)
	(supports instrument7 infrared3)
	(calibration_target instrument7 GroundStation3)
	(on_board instrument6 satellite2)
	(on_board instrument7 satellite2)
	(power_avail satellite2)
	(pointing satellite2 GroundStation7)
	(supports instrument8 spectrograph1)
	(supports instrument8 infrared3)
	(calibration_target instrument8 Star6)
	(calibration_target instrument8 Star1)
	(calibration_target instrument8 GroundStation5)
	(supports instrument9 infrared3)
	(supports instrument9 image0)
	(calibration_target instrument9 Star6)
	(calibration_target instrument9 GroundStation9)
	(supports instrument10 infrared3)
	(calibration_target instrument10 GroundStation8)
	(calibration_target instrument10 Star4)
	(supports instrument11 image0)
	(supports instrument11 spectrograph1)
	(calibration_target instrument11 GroundStation2)
	(calibration_target instrument11 GroundStation3)
	(calibration_target instrument11 GroundStation5)
	(on_board instrument8 satellite3)
	(on_board instrument9 satellite3)
	(on_board instrument10 satellite3)
	(on_board instrument11 satellite3)
	(power_avail satellite3)
	(pointing satellite3 Planet13)
	(supports instrument12 spectrograph2)
	(supports instrument12 image4)
	(supports instrument12 image0)
	(calibration_target instrument12 GroundStation2)
	(calibration_target instrument12 GroundStation5)
	(supports instrument13 infrared3)
	(supports instrument13 spectrograph1)
	(calibration_target instrument13 GroundStation7)
	(calibration_target instrument13 GroundStation3)
	(calibration_target instrument13 GroundStation8)
	(supports instrument14 infrared3)
	(supports instrument14 spectrograph1)
	(supports instrument14 image0)
	(calibration_target instrument14 GroundStation8)
	(on_board instrument12 satellite4)
	(on_board instrument13 satellite4)
	(on_board instrument14 satellite4)
	(power_avail satellite4)
	(pointing satellite4 Star10)
)
(:goal (and
	
	
	
	(have_image Star10 spectrograph2)
	(have_image Planet11 infrared3)
	(have_image Star12 infrared3)
	(have_image Planet13 image0)
	(have_image Phenomenon14 infrared3)
	(have_image Planet15 spectrograph1)
	(have_image Star16 image0)
	(have_image Phenomenon17 image0)
	(have_image Star18 spectrograph1)
	(have_image Phenomenon19 spectrograph1)
	(have_image Phenomenon20 image0)
	(have_image Planet22 spectrograph1)
	(have_image Phenomenon23 infrared3)
	(have_image Planet24 image4)
	(have_image Planet25 spectrograph2)
	(have_image Planet26 spectrograph1)
	(have_image Star27 spectrograph1)
	(have_image Star28 spectrograph2)
	(have_image Star29 image4)
))
(:metric minimize (total-time))

)
