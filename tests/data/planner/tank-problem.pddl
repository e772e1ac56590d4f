(define (problem fill-tank) (:domain tank) (:init (open) (= (level) 0)) (:goal (>= (level) 4)))
